#!/usr/bin/env bash
# fgsg run --camera (#49): `fit` is the default preview byte for byte; an orbit camera
# draws another picture, the same for the same camera; bad values, unknown keys and a
# --camera without --preview are usage errors (exit 2) that name what is wrong and write
# nothing. Which side each camera shows is checked in tests/unit/runtime/test_preview.cpp.
#   preview_camera.sh FGSG SOURCE_DIR
set -u
fgsg="$1" source="$2"
fail=0
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
export FGSG_CACHE_DIR="$work/cache"
grammar="$source/examples/mueller_building.fgsg"

preview() {  # NAME ARGS...: the preview NAME.png of the building
  local name="$1"
  shift
  "$fgsg" run "$grammar" -o "$name.glb" --preview "$name.png" -q "$@" || { echo "FAIL: fgsg run $* exited $?"; fail=1; }
}
preview default
preview fit --camera fit
preview front --camera azimuth=90,elevation=10
preview front_again --camera elevation=10,azimuth=90
preview back --camera azimuth=-90,elevation=10
preview far --camera azimuth=90,elevation=10,distance=500
cmp -s default.png fit.png || { echo "FAIL: --camera fit changes the default preview"; fail=1; }
cmp -s front.png front_again.png || { echo "FAIL: the same camera drew two pictures"; fail=1; }
for other in front back far; do
  cmp -s default.png "$other.png" && { echo "FAIL: --camera for $other drew the default picture"; fail=1; }
done
cmp -s front.png back.png && { echo "FAIL: the front and the back look the same"; fail=1; }
cmp -s front.png far.png && { echo "FAIL: the distance changes nothing"; fail=1; }

expect() {  # CODE TEXT ARGS...: the run exits CODE and prints TEXT
  local code="$1" line="$2" out rc
  shift 2
  out="$("$fgsg" "$@" 2>&1 </dev/null)"
  rc=$?
  if [ "$rc" -ne "$code" ] || ! grep -qF -- "$line" <<<"$out"; then
    echo "FAIL: fgsg $* exited $rc (expected $code), printing:"; echo "$out"; echo "expected: $line"; fail=1
  fi
}
bad() {  # TEXT CAMERA: --camera CAMERA is refused with TEXT
  expect 2 "fgsg run: $1" run "$grammar" -o bad.glb --preview bad.png --camera "$2"
}
bad "--camera elevation=95: the camera's elevation is 95, not between -90 and 90 degrees" elevation=95
bad "--camera elevation=-90.5: the camera's elevation is -90.5, not between -90 and 90 degrees" elevation=-90.5
bad "--camera distance=0: the distance must be positive (scene units)" distance=0
bad "--camera distance=-3: the distance must be positive (scene units)" distance=-3
bad "--camera azimuth expects a number, got 'west'" azimuth=west
bad "--camera azimuth expects a number, got 'inf'" azimuth=inf
bad "--camera azimuth=1,azimuth=2: azimuth is given twice" azimuth=1,azimuth=2
bad "--camera azimth=3: 'azimth=3' is not azimuth=DEG, elevation=DEG or distance=D; did you mean azimuth?" azimth=3
bad "--camera zoom=3: 'zoom=3' is not azimuth=DEG, elevation=DEG or distance=D (fit, or azimuth=DEG" zoom=3
bad "--camera 30,20: '30' is not azimuth=DEG" 30,20
bad "--camera expects fit, or azimuth=DEG,elevation=DEG,distance=D (each optional), got nothing" ""
expect 2 "fgsg run: --camera sets the preview's view: it needs --preview FILE.png" run "$grammar" -o bad.glb --camera fit
expect 2 "fgsg run: unknown option '--camra'; did you mean --camera? (see fgsg run --help)" run "$grammar" --camra fit
ls bad.* >/dev/null 2>&1 && { echo "FAIL: a refused run wrote a file"; fail=1; }
exit $fail

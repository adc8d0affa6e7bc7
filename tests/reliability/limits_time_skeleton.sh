#!/usr/bin/env bash
# --max-seconds holds on a large CGA lot (issue 42, L1). A valid comb-shaped lot of 500
# teeth (2 003 corners) took 53 s with --max-seconds 2 in examples/city.fgsg: each leaf
# face of 2 000 corners (the flat roof, the parapet's band) was ear-clipped in cubic time,
# all of it inside one rewrite. And CGAL's straight skeleton (Offset, Roof), which
# cannot be interrupted, grows with the corners too: it runs on a worker abandoned at
# the limit. Both engines; R004 and what was derived is written. Bounds are loose (a
# loaded 2-core machine) but far below the minute the lots took.
. "$(dirname "$0")/lib.sh"
skip_under_asan "it times --max-seconds"
export FGSG_CACHE_DIR=off

# comb TEETH ROOF FILE [LENGTH]: one lot, a serpentine of TEETH teeth 1 m apart, LENGTH
# (1 000) metres long (the reproducer's).
comb() {
  python3 - "$1" "$2" "$3" "${4:-1000}" <<'P'
import json, sys
teeth, roof, path, n = int(sys.argv[1]), sys.argv[2], sys.argv[3], int(sys.argv[4])
h = 2 * teeth
ring = [[0, 0], [n, 0]]
for y in range(1, h):
    ring += [[n, y], [1, y]] if y % 2 else [[1, y], [n, y]]
ring += [[1, h], [0, h], [0, 0]]
lot = {"type": "Feature", "properties": {"height": 9, "floors": 3, "usage": "office", "roof": roof},
       "geometry": {"type": "Polygon", "coordinates": [ring]}}
json.dump({"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},
           "features": [lot]}, open(path, "w"))
P
}
comb 500 flat "$tmp/comb_flat.geojson"  # the flat roof's parapet: Offset(0.35) on the top face
comb 500 hipped "$tmp/comb_hipped.geojson"
comb 2500 flat "$tmp/comb_large.geojson"  # 10 003 corners: the skeleton alone takes minutes
printf 'axiom: Lot;\nLot ~> Offset(0.35){ inside: A | border: B };\nA ~> I("cube");\nB ~> I("cube");\n' >"$tmp/offset.fgsg"
printf 'axiom: Lot;\nLot ~> Roof("hipped", 30){ R };\nR ~> I("cube");\n' >"$tmp/roof.fgsg"

t_start() { t0=$(date +%s.%N); }
t_below() {  # t_below LIMIT WHAT
  local took
  took=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
  awk -v t="$took" -v l="$1" 'BEGIN { exit !(t < l) }' || fail "$2 took $took s, more than $1 s"
}

for engine in interp jit; do
  for op in offset roof; do
    t_start
    expect 0 'warning\[R004\]: derivation stopped after 1\.0+ s \(--max-seconds\)' -- \
      "$fgsg" run "$tmp/$op.fgsg" --lots "$tmp/comb_large.geojson" --max-seconds 1 --engine "$engine" -o "$tmp/$op.obj"
    t_below 4 "$op on a 10 003-corner lot with --max-seconds 1 ($engine)"
    [ -e "$tmp/$op.obj" ] || fail "nothing was written after the $op skeleton was abandoned ($engine)"
  done
done

cd "$root/examples" || fail "no examples folder"
stopped='warning\[R004\]: derivation stopped after 2\.0+ s \(--max-seconds\); the shapes derived so far are kept'
for engine in interp jit; do
  for roof in flat hipped; do
    t_start
    expect 0 "$stopped" -- "$fgsg" run city.fgsg --lots "$tmp/comb_$roof.geojson" --max-seconds 2 --engine "$engine" \
      -o "$tmp/comb.obj" --stats
    t_below 6 "the $roof comb lot with --max-seconds 2 ($engine)"
    [ -s "$tmp/comb.obj" ] || fail "the kept result of the $roof comb lot was not written ($engine)"
    # The derivation itself ends soon after the limit (unloaded: within 10 %; a loaded
    # machine has reached 2.47).
    awk '$1 == "time.derive" { exit !($2 >= 2.0 && $2 < 2.8) }' "$tmp/out" ||
      fail "time.derive $(awk '$1 == "time.derive" { print $2 }' "$tmp/out") for --max-seconds 2 ($roof, $engine)"
  done
done

# A small comb (40 teeth, 163 corners: past the inline size, on a worker) is still built
# whole and gives the same output as a run without a limit (1e10 s: none, on this thread).
comb 40 flat "$tmp/small.geojson" 30
mkdir -p "$tmp/a" "$tmp/b"
expect 0 '' -- "$fgsg" run city.fgsg --lots "$tmp/small.geojson" --engine interp --max-seconds 1e10 -o "$tmp/a/small.obj"
expect 0 '' -- "$fgsg" run city.fgsg --lots "$tmp/small.geojson" --engine interp --max-seconds 60 -o "$tmp/b/small.obj"
! grep -q R004 "$tmp/err" || fail "the small comb lot stopped at --max-seconds 60"
cmp -s "$tmp/a/small.obj" "$tmp/b/small.obj" || fail "the small comb lot differs with --max-seconds 60"
exit 0

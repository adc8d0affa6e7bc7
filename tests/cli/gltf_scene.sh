#!/usr/bin/env bash
# fgsg run --instancing / --group-by (issue #45): the structured, instanced glTF scene.
# The 200-lot city and stem_leaf are written flattened (the default: today's bytes) and
# as scenes; each scene passes the Khronos validator with no errors and no warnings, and
# an independent reader (gltf_scene_check.py) finds a node per start shape named after
# its lot, as many instances per asset as --instances lists, and the world bounds of the
# flattened file. The byte ratios are printed.
. "$(dirname "$0")/../reliability/lib.sh"
python=/usr/bin/python3
[ -x "$python" ] || python=python3
check="$root/tests/cli/gltf_scene_check.py"
ex="$root/examples"

validate() {  # FILE: 0 errors and 0 warnings
  node "$root/scripts/validate-gltf.js" --strict "$1" >"$tmp/validator" 2>&1 ||
    { cat "$tmp/validator" >&2; fail "gltf-validator: $(basename "$1") has errors or warnings"; }
  grep -q ': 0 errors, 0 warnings' "$tmp/validator" || { cat "$tmp/validator" >&2; fail "no validator summary"; }
}

run() { timeout 120 "$fgsg" run "$@" -q 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "fgsg run $*"; }; }

# The city: flattened (the default, and --instancing off --group-by none: the same bytes).
lots="$ex/city/lots.geojson"
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_flat.glb" --instances "$tmp/city.json"
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_off.glb" --instancing off --group-by none
cmp -s "$tmp/city_flat.glb" "$tmp/city_off.glb" || fail "--instancing off --group-by none changed the flattened bytes"
for mode in on auto; do
  run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_$mode.glb" --instancing $mode --group-by symbol
  validate "$tmp/city_$mode.glb"
  "$python" "$check" "$tmp/city_$mode.glb" "$tmp/city_flat.glb" "$tmp/city.json" --starts 200 \
    --start-names "$lots" --expect-instanced >"$tmp/check" 2>&1 || { cat "$tmp/check" >&2; fail "city, --instancing $mode"; }
  echo "city --instancing $mode: $(grep '^bytes' "$tmp/check")"
done
# Other groupings and the text form.
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_rule.gltf" --instancing auto --group-by rule
validate "$tmp/city_rule.gltf"
"$python" "$check" "$tmp/city_rule.gltf" "$tmp/city_flat.glb" "$tmp/city.json" --starts 200 >"$tmp/check" 2>&1 ||
  { cat "$tmp/check" >&2; fail "city, --group-by rule (.gltf)"; }
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_label.glb" --instancing off --group-by label
validate "$tmp/city_label.glb"
"$python" "$check" "$tmp/city_label.glb" "$tmp/city_flat.glb" "$tmp/city.json" --starts 200 >"$tmp/check" 2>&1 ||
  { cat "$tmp/check" >&2; fail "city, --instancing off --group-by label"; }

# stem_leaf: 1921 instances of a few assets, one start shape (and the surface).
run "$ex/stem_leaf.fgsg" -o "$tmp/stem_flat.glb" --instances "$tmp/stem.json"
run "$ex/stem_leaf.fgsg" -o "$tmp/stem_on.glb" --instancing on --group-by symbol
validate "$tmp/stem_on.glb"
"$python" "$check" "$tmp/stem_on.glb" "$tmp/stem_flat.glb" "$tmp/stem.json" --starts 1 --expect-instanced \
  >"$tmp/check" 2>&1 || { cat "$tmp/check" >&2; fail "stem_leaf, --instancing on"; }
echo "stem_leaf --instancing on: $(grep '^bytes' "$tmp/check")"

# Usage: unknown values, and a scene asked of a format that has none.
expect 2 "--instancing sometimes: use auto, on or off" -- "$fgsg" run "$ex/stem_leaf.fgsg" --instancing sometimes
expect 2 "--group-by colour: use symbol, rule, label or none" -- "$fgsg" run "$ex/stem_leaf.fgsg" --group-by colour
expect 2 "lay out a glTF scene" -- "$fgsg" run "$ex/stem_leaf.fgsg" -o "$tmp/x.obj" --instancing on
echo "ok"

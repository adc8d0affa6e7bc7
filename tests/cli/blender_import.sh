#!/usr/bin/env bash
# Blender as the client of fgsg's output (issue #45): Debian's blender, headless, imports
# six lots of the city as a glTF scene (--instancing nodes: a node per instance, which
# Blender 3.4's importer, without EXT_mesh_gpu_instancing, makes linked duplicates) and as
# a grouped OBJ with its .mtl, and blender_check.py checks objects per lot, instance
# counts, materials and the up axis there; then the same glTF scene written with
# --quantize, every vertex within 1 mm of the float one's. Blender is installed by the test set-up only
# (scripts/install-deps.sh --test): without it this test fails.
. "$(dirname "$0")/../reliability/lib.sh"
command -v blender >/dev/null 2>&1 ||
  fail "blender is not installed (scripts/install-deps.sh --test installs Debian's blender for the tests)"
ex="$root/examples"
# Six lots of the city (some 2000 instances: Blender makes an object of each).
lots="$tmp/lots.geojson"
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); d["features"] = d["features"][:6]; json.dump(d, open(sys.argv[2], "w"))' \
  "$ex/city/lots.geojson" "$lots" || fail "no lots"
run() { timeout 120 "$fgsg" run "$@" -q 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "fgsg run $*"; }; }
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city.glb" --instancing nodes
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city.obj" --group-by symbol
# ... and quantized (--quantize: KHR_mesh_quantization, KHR_texture_transform).
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_q.glb" --instancing nodes --quantize
# Blender keeps its settings and caches under HOME: a fresh one each run.
mkdir -p "$tmp/home"
HOME="$tmp/home" timeout 300 blender -b --factory-startup --python-exit-code 1 \
  --python "$root/tests/cli/blender_check.py" -- "$tmp/city.glb" "$tmp/city.obj" "$lots" "$tmp/city_q.glb" >"$tmp/blender" 2>&1
status=$?
grep -E '^(FAIL|roots|instances|materials|up axis|OBJ|quantized|blender ok)' "$tmp/blender"
[ $status -eq 0 ] && grep -q '^blender ok' "$tmp/blender" || { tail -40 "$tmp/blender" >&2; fail "Blender's import (exit $status)"; }
echo "ok"

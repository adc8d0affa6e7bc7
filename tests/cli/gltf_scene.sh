#!/usr/bin/env bash
# fgsg run's structured output (issue #45). The 200-lot city and stem_leaf are written
# flattened (--instancing off --group-by none: the bytes of before the scene existed) and
# as scenes (the default for .glb: auto / symbol); each scene passes the Khronos validator
# with no errors and no warnings, and an independent reader (gltf_scene_check.py) finds a
# node per start shape named after its lot, as many instances per asset as --instances
# lists, and the world bounds of the flattened file. The byte ratios are printed. Then
# the grouped OBJ with its .mtl, and --split-output's files and manifest.
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

# The city: flattened, byte for byte the .glb every fgsg wrote before the scene (its
# sha256 as of commit 571dbea; a change of the derivation itself changes it).
lots="$ex/city/lots.geojson"
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_flat.glb" --instances "$tmp/city.json" --instancing off --group-by none
flat_sha=e0be509869ac650cf06970da12f27ae8bee0b05e1785b50a8508e8115f8f46f3
[ "$(sha256sum <"$tmp/city_flat.glb" | cut -d' ' -f1)" = "$flat_sha" ] ||
  fail "--instancing off --group-by none no longer writes the flattened bytes of before"
# The default is the scene: --instancing auto --group-by symbol.
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_default.glb"
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_auto.glb" --instancing auto --group-by symbol
cmp -s "$tmp/city_default.glb" "$tmp/city_auto.glb" || fail "the default is not --instancing auto --group-by symbol"
# The default scene's bytes: 0.300 of the flattened file's with a buffer view per accessor
# and min/max as 17-digit doubles; 0.290 with the views pooled and shortest min/max;
# 0.277 with an instanced node's one scale (the windows') in its mesh, SCALE left out
# (docs/cli.md; the issue's 0.10 is not reached). --instancing on instances even two
# equal pieces: 2.34 before, 1.98, now 1.97.
max_ratio_on=2.0 max_ratio_auto=0.28
for mode in on auto; do
  run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_$mode.glb" --instancing $mode --group-by symbol
  validate "$tmp/city_$mode.glb"
  max_ratio=max_ratio_$mode
  "$python" "$check" "$tmp/city_$mode.glb" "$tmp/city_flat.glb" "$tmp/city.json" --starts 200 \
    --start-names "$lots" --expect-instanced --max-ratio "${!max_ratio}" >"$tmp/check" 2>&1 ||
    { cat "$tmp/check" >&2; fail "city, --instancing $mode"; }
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
run "$ex/stem_leaf.fgsg" -o "$tmp/stem_flat.glb" --instances "$tmp/stem.json" --instancing off --group-by none
run "$ex/stem_leaf.fgsg" -o "$tmp/stem_on.glb" --instancing on --group-by symbol
validate "$tmp/stem_on.glb"
"$python" "$check" "$tmp/stem_on.glb" "$tmp/stem_flat.glb" "$tmp/stem.json" --starts 1 --expect-instanced \
  >"$tmp/check" 2>&1 || { cat "$tmp/check" >&2; fail "stem_leaf, --instancing on"; }
echo "stem_leaf --instancing on: $(grep '^bytes' "$tmp/check")"

# The grouped OBJ: an `o` per lot named after it, `g` per symbol, its .mtl beside it with
# every material it uses (Kd, map_Kd relative to the .mtl, the image there).
mkdir -p "$tmp/obj"
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/obj/city.obj" --group-by symbol
"$python" - "$tmp/obj/city.obj" "$lots" "$tmp/city.json" <<'PY' || fail "grouped OBJ"
import json, os, sys
obj, lots, listed = sys.argv[1:4]
lines = open(obj).read().splitlines()
assert lines[1] == "mtllib city.mtl", lines[:2]
objects = [l[2:] for l in lines if l.startswith("o ")]
ids = [str(f["id"]) for f in json.load(open(lots))["features"]]
assert objects == ids, (objects[:3], ids[:3])
groups = {l[2:] for l in lines if l.startswith("g ")}
symbols = {i["symbol"] for i in json.load(open(listed))["instances"]}
assert groups <= symbols and "Wall" in groups and "Glass" in groups, (groups, symbols)
used = {l.split()[1] for l in lines if l.startswith("usemtl ")}
mtl = open(os.path.join(os.path.dirname(obj), "city.mtl")).read().split("\nnewmtl ")[1:]
defined = {}
for block in mtl:
    words = block.split("\n")
    defined[words[0]] = dict(l.split(" ", 1) for l in words[1:] if l)
assert used == set(defined), (used, set(defined))
for name, m in defined.items():
    kd = [float(x) for x in m["Kd"].split()]
    assert len(kd) == 3 and all(0 <= x <= 1 for x in kd), (name, kd)
    if "map_Kd" in m:
        assert os.path.isfile(os.path.join(os.path.dirname(obj), m["map_Kd"])), m["map_Kd"]
assert defined["7d9b55"]["Kd"] == "0.49019608 0.60784316 0.33333334", defined["7d9b55"]  # the yards, #7d9b55
faces = sum(1 for l in lines if l.startswith("f "))
print(f"grouped OBJ: {len(objects)} objects, {len(groups)} groups, {len(defined)} materials, {faces} faces")
PY

# --split-output: a file per lot named after it and a manifest whose triangles and
# bounds add up to the whole city's.
run "$ex/city.fgsg" --lots "$lots" --split-output "$tmp/split"
validate "$tmp/split/$(ls "$tmp/split" | head -1)"
"$python" - "$tmp/split" "$lots" "$tmp/city_flat.glb" <<'PY' || fail "--split-output"
import json, os, struct, sys
folder, lots, flat = sys.argv[1:4]
m = json.load(open(os.path.join(folder, "manifest.json")))
ids = [str(f["id"]) for f in json.load(open(lots))["features"]]
assert [f["name"] for f in m["files"]] == ids, [f["name"] for f in m["files"]][:3]
assert sorted(os.listdir(folder)) == sorted([f["file"] for f in m["files"]] + ["manifest.json"])
for f in m["files"]:
    data = open(os.path.join(folder, f["file"]), "rb").read()
    assert data[:4] == b"glTF" and struct.unpack_from("<I", data, 8)[0] == len(data), f["file"]
    doc = json.loads(data[20:20 + struct.unpack_from("<I", data, 12)[0]])
    assert [doc["nodes"][r]["name"] for r in doc["scenes"][0]["nodes"]] == [f["name"]], f["file"]
data = open(flat, "rb").read()
doc = json.loads(data[20:20 + struct.unpack_from("<I", data, 12)[0]])
triangles = sum(doc["accessors"][p["indices"]]["count"] // 3 for mesh in doc["meshes"] for p in mesh["primitives"] if p.get("mode", 4) == 4)
pos = [doc["accessors"][p["attributes"]["POSITION"]] for mesh in doc["meshes"] for p in mesh["primitives"]]
total = sum(f["triangles"] for f in m["files"])
assert total == triangles, (total, triangles)
lo = [min(f["bounds"]["min"][d] for f in m["files"]) for d in range(3)]
hi = [max(f["bounds"]["max"][d] for f in m["files"]) for d in range(3)]
assert max(abs(a - b) for a, b in zip(lo, pos[0]["min"])) < 1e-3 and max(abs(a - b) for a, b in zip(hi, pos[0]["max"])) < 1e-3, (lo, hi, pos[0]["min"], pos[0]["max"])
print(f"split: {len(m['files'])} files, {total} triangles as the flattened file, bounds {lo}..{hi}")
PY
# ... as grouped OBJs, each with its .mtl.
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/x.obj" --group-by symbol --split-output "$tmp/split_obj"
[ "$(ls "$tmp/split_obj" | grep -c '\.obj$')" = 200 ] && [ "$(ls "$tmp/split_obj" | grep -c '\.mtl$')" = 200 ] ||
  fail "--split-output with -o .obj: not an OBJ and a .mtl per lot"

# Usage: unknown values, and a scene asked of a format that has none.
expect 2 "--instancing sometimes: use auto, on, nodes or off" -- "$fgsg" run "$ex/stem_leaf.fgsg" --instancing sometimes
expect 2 "--group-by colour: use symbol, rule, label or none" -- "$fgsg" run "$ex/stem_leaf.fgsg" --group-by colour
expect 2 "OBJ has no instances" -- "$fgsg" run "$ex/stem_leaf.fgsg" -o "$tmp/x.obj" --instancing on
expect 2 "PLY is one flattened mesh" -- "$fgsg" run "$ex/stem_leaf.fgsg" -o "$tmp/x.ply" --group-by symbol
expect 2 "PLY is one flattened mesh" -- "$fgsg" run "$ex/stem_leaf.fgsg" -o "$tmp/x.ply" --split-output "$tmp/s"
echo "ok"

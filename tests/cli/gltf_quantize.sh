#!/usr/bin/env bash
# fgsg run --quantize (issue #45): the glTF scene's vertex data as 16-bit integers
# (KHR_mesh_quantization, required by the file; KHR_texture_transform scales the texture
# coordinates back). Each quantized file passes the Khronos validator with no errors and
# no warnings; gltf_quantized_check.py decodes it and the float scene of the same run
# independently and compares every placed vertex (positions within 0.5 mm, normals,
# texture coordinates up to whole tiles); gltf_scene_check.py checks the city's nodes,
# instance counts and bounds against the flattened file and pins the byte ratio.
. "$(dirname "$0")/../reliability/lib.sh"
python=/usr/bin/python3
[ -x "$python" ] || python=python3
ex="$root/examples"

validate() {  # FILE: 0 errors and 0 warnings
  node "$root/scripts/validate-gltf.js" --strict "$1" >"$tmp/validator" 2>&1 ||
    { cat "$tmp/validator" >&2; fail "gltf-validator: $(basename "$1") has errors or warnings"; }
  grep -q ': 0 errors, 0 warnings' "$tmp/validator" || { cat "$tmp/validator" >&2; fail "no validator summary"; }
}
run() { timeout 120 "$fgsg" run "$@" -q 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "fgsg run $*"; }; }
compare() {  # QUANTIZED FLOAT [TOLERANCE]: vertex by vertex
  "$python" "$root/tests/cli/gltf_quantized_check.py" "$1" "$2" --position-tolerance "${3:-5e-4}" >"$tmp/check" 2>&1 ||
    { cat "$tmp/check" >&2; fail "$(basename "$1") against $(basename "$2")"; }
  echo "$(basename "$1"): $(head -1 "$tmp/check")"
}

# The 200-lot city: the default scene (auto / symbol) and --instancing on, each against
# its float scene: within 0.5 mm, 1 mm with --instancing on (its wall pieces
# turned by 16-bit rotations: measured 0.47 mm).
lots="$ex/city/lots.geojson"
run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_flat.glb" --instances "$tmp/city.json" --instancing off --group-by none
for mode in auto on; do
  run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_$mode.glb" --instancing $mode
  run "$ex/city.fgsg" --lots "$lots" -o "$tmp/city_${mode}_q.glb" --instancing $mode --quantize
  validate "$tmp/city_${mode}_q.glb"
  tolerance=5e-4
  [ $mode = on ] && tolerance=1e-3
  compare "$tmp/city_${mode}_q.glb" "$tmp/city_$mode.glb" $tolerance
done
# Nodes, instance counts and world bounds as the flattened file's (to the grid's half
# step); the bytes: 0.290 of the flattened file's unquantized, 0.213 quantized (uvs in
# steps of 1/4096 tile at least, floats where they span more than 16 tiles)
# (docs/cli.md).
"$python" "$root/tests/cli/gltf_scene_check.py" "$tmp/city_auto_q.glb" "$tmp/city_flat.glb" "$tmp/city.json" \
  --starts 200 --start-names "$lots" --expect-instanced --tolerance 5e-4 --max-ratio 0.22 >"$tmp/check" 2>&1 ||
  { cat "$tmp/check" >&2; fail "city --quantize against the flattened file"; }
echo "city --quantize: $(grep '^bytes' "$tmp/check")"
"$python" - "$tmp/city_auto_q.glb" <<'PY' || fail "city --quantize: its extensions and accessors"
import json, struct, sys
data = open(sys.argv[1], "rb").read()
doc = json.loads(data[20:20 + struct.unpack_from("<I", data, 12)[0]])
assert doc["extensionsRequired"] == ["KHR_mesh_quantization", "KHR_texture_transform"], doc["extensionsRequired"]
acc = doc["accessors"]
walls = [m for m in doc["meshes"] if m["name"] == "Wall"]
shortUvs = 0
for m in walls:
    for p in m["primitives"]:
        pos, uv = acc[p["attributes"]["POSITION"]], acc[p["attributes"]["TEXCOORD_0"]]
        assert (pos["componentType"], pos.get("normalized", False)) == (5123, False), pos
        # 16-bit in steps of 1/4096 tile or finer; floats where they span more than 16 tiles
        assert uv["componentType"] in (5122, 5126), uv
        shortUvs = shortUvs + 1 if uv["componentType"] == 5122 else shortUvs
        if uv["componentType"] == 5126:
            continue
        scale = doc["materials"][p["material"]]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"]["scale"]
        assert scale[0] == scale[1] and 2 ** -14 <= scale[0] <= 2 ** -12, scale
assert shortUvs > 0, "no wall with 16-bit texture coordinates"
# A baked wall's node holds its mesh with the grid's transform (it has no children).
node = next(n for n in doc["nodes"] if n.get("name") == "Wall")
assert "mesh" in node and len(set(node["scale"])) == 1 and 0 < node["scale"][0] < 1e-3, node
rotations = [acc[n["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["ROTATION"]] for n in doc["nodes"] if "extensions" in n]
assert rotations and all(r["componentType"] == 5122 and r["normalized"] for r in rotations), rotations[:1]
print(f"city --quantize: {len(walls)} wall meshes 16-bit ({shortUvs} primitives with 16-bit uvs), {len(rotations)} instanced nodes with 16-bit rotations")
PY

# Smooth normals (stem_leaf's spheres: shared meshes instanced, and baked with
# --instancing off), a normal map's tangents and texture layers (materials.fgsg), CGA's
# uv sets 1..9 (uv_layers.fgsg, which stay floats), on a lot each as run_materials.py
# derives them (their images under textures/ beside the grammar).
ln -s "$ex/textures" "$tmp/textures"
cp "$root/tests/cga/materials/materials.fgsg" "$root/tests/cga/materials/uv_layers.fgsg" "$tmp/"
corpus_lots="$root/tests/cga/corpus/lots"
for case in "stem_leaf:$ex/stem_leaf.fgsg:on:" "stem_baked:$ex/stem_leaf.fgsg:off:" \
            "materials:$tmp/materials.fgsg:auto:$corpus_lots/rect20x10.geojson" \
            "uv_layers:$tmp/uv_layers.fgsg:auto:$corpus_lots/street40x12.geojson"; do
  IFS=: read -r name grammar mode lot <<<"$case"
  lot_args=()
  [ -n "$lot" ] && lot_args=(--lots "$lot")
  run "$grammar" "${lot_args[@]}" -o "$tmp/$name.glb" --instancing "$mode"
  run "$grammar" "${lot_args[@]}" -o "$tmp/${name}_q.glb" --instancing "$mode" --quantize
  validate "$tmp/${name}_q.glb"
  compare "$tmp/${name}_q.glb" "$tmp/$name.glb"
done
grep -q '"TANGENT"' "$tmp/materials_q.glb" || fail "materials.fgsg: no tangents written"

# --split-output: each lot's file quantized.
run "$ex/city.fgsg" --lots "$lots" --split-output "$tmp/split" --quantize
validate "$tmp/split/$(ls "$tmp/split" | grep -m1 '\.glb$')"
grep -q KHR_mesh_quantization "$tmp/split/$(ls "$tmp/split" | grep -m1 '\.glb$')" || fail "--split-output: not quantized"

# Usage: --quantize encodes the glTF scene only.
expect 2 "--quantize encodes a glTF scene" -- "$fgsg" run "$ex/stem_leaf.fgsg" -o "$tmp/x.obj" --quantize
expect 2 "--quantize encodes a glTF scene" -- "$fgsg" run "$ex/stem_leaf.fgsg" -o "$tmp/x.glb" --quantize --instancing off --group-by none
expect 2 "--quantize encodes a glTF scene" -- "$fgsg" run "$ex/stem_leaf.fgsg" -o "$tmp/x.ply" --quantize
echo "ok"

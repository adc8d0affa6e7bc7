#!/usr/bin/env bash
# CGA on GeoJSON lots as a user meets it: the city block builds in both engines with the
# same bytes, the same seed gives the same city and another seed another one, the lots
# file is the one scripts/make_city_lots.py writes (the textures the ones
# scripts/make_textures.py draws), a textured OBJ comes with its .mtl, and a broken lots
# file is a located error with exit 2.
. "$(dirname "$0")/../reliability/lib.sh"
cd "$root" || fail "no $root"

lots=examples/city/lots.geojson
python3 scripts/make_city_lots.py -o "$tmp/lots.geojson" --check >/dev/null || fail "make_city_lots.py failed"
cmp -s "$tmp/lots.geojson" "$lots" || fail "$lots is not what scripts/make_city_lots.py writes"
python3 scripts/make_textures.py "$tmp/textures" || fail "make_textures.py failed"
for image in "$tmp"/textures/*.png; do
  cmp -s "$image" "examples/textures/$(basename "$image")" || fail "examples/textures/$(basename "$image") is not what scripts/make_textures.py draws"
done
[ "$(ls "$tmp/textures" | wc -l)" -eq "$(ls examples/textures | wc -l)" ] || fail "examples/textures holds images the script does not draw"

# Same names in two folders: a textured OBJ names its .mtl, which names the images.
mkdir -p "$tmp/i" "$tmp/j"
"$fgsg" run examples/city.fgsg --lots "$lots" --engine interp -q -o "$tmp/i/city.obj" || fail "interpreter: exit $?"
"$fgsg" run examples/city.fgsg --lots "$lots" --engine jit --stats -o "$tmp/j/city.obj" >"$tmp/stats" 2>&1 || fail "JIT: exit $?"
cmp -s "$tmp/i/city.obj" "$tmp/j/city.obj" || fail "the engines wrote different bytes"
cmp -s "$tmp/i/city.mtl" "$tmp/j/city.mtl" || fail "the engines wrote different materials"
grep -q '^mtllib city.mtl$' "$tmp/i/city.obj" || fail "the OBJ does not name its materials file"
grep -q '^map_Kd .*examples/textures/brick.png$' "$tmp/i/city.mtl" || fail "the materials do not point at the brick image"
[ -f "$(dirname "$tmp/i/city.mtl")/$(awk '$1 == "map_Kd" {print $2; exit}' "$tmp/i/city.mtl")" ] ||
  fail "the first map_Kd path does not reach its image from the .mtl's folder"
instances=$(awk '$1 == "instances" {print $2}' "$tmp/stats")
[ "${instances:-0}" -gt 20000 ] || fail "only ${instances:-no} instances for 200 lots"
"$fgsg" run examples/city.fgsg --lots "$lots" --seed 3 -q -o "$tmp/s3.obj" || fail "seed 3: exit $?"
cmp -s "$tmp/i/city.obj" "$tmp/s3.obj" && fail "another seed gave the same city"

# Geometries other than polygons are passed over, and said so (not with --quiet).
printf '{"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}}, "features": [
  {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [1, 2]}},
  {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]]]}}]}' >"$tmp/point.geojson"
expect 0 'point.geojson: 1 geometry that is not a polygon was passed over' -- \
  "$fgsg" run examples/city.fgsg --lots "$tmp/point.geojson" -o "$tmp/p.glb"
"$fgsg" run examples/city.fgsg --lots "$tmp/point.geojson" -q -o "$tmp/p.glb" 2>"$tmp/quiet" || fail "--quiet: exit $?"
grep -q "passed over" "$tmp/quiet" && fail "--quiet still says the point was passed over"

# Broken lots: located errors, exit 2, nothing written.
printf '{"type": "FeatureCollection", "features": [{"type": "Feature", "id": "bad", "properties": {},
  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 1], [1, 0], [0, 1], [0, 0]]]}}]}' >"$tmp/bowtie.geojson"
expect 2 'feature 0 \(id "bad"\).*cross' -- "$fgsg" run examples/city.fgsg --lots "$tmp/bowtie.geojson" -o "$tmp/x.glb"
[ -e "$tmp/x.glb" ] && fail "a broken lots file still wrote a mesh"
printf '{"type": "FeatureCollection", "features": []}' >"$tmp/empty.geojson"
expect 2 'no Polygon or MultiPolygon' -- "$fgsg" run examples/city.fgsg --lots "$tmp/empty.geojson" -o "$tmp/x.glb"
printf '{"type": "FeatureCollection", "features": [' >"$tmp/cut.geojson"
expect 2 'cut.geojson:1:44: not valid JSON' -- "$fgsg" run examples/city.fgsg --lots "$tmp/cut.geojson" -o "$tmp/x.glb"
expect 2 'no-such.geojson' -- "$fgsg" run examples/city.fgsg --lots "$tmp/no-such.geojson" -o "$tmp/x.glb"
# A lot property of the wrong type for its attr: the lot is named, exit 1.
printf '{"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}}, "features": [{"type": "Feature", "id": "L9", "properties": {"height": "tall"},
  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]]]}}]}' >"$tmp/tall.geojson"
expect 1 'feature 0 \(id "L9"\): property height=tall: expected a number' -- \
  "$fgsg" run examples/city.fgsg --lots "$tmp/tall.geojson" -o "$tmp/x.glb"
# Lots from a mesh's polygon faces (Y up): an L-shaped face and a rectangle, two buildings.
printf 'v 0 0 0\nv 20 0 0\nv 20 0 -9\nv 9 0 -9\nv 9 0 -18\nv 0 0 -18\nv 30 0 0\nv 45 0 0\nv 45 0 -12\nv 30 0 -12\nf 1 2 3 4 5 6\nf 7 8 9 10\n' >"$tmp/block.obj"
"$fgsg" run examples/city.fgsg --lots "$tmp/block.obj" --stats -o "$tmp/block.glb" >"$tmp/block.stats" 2>&1 || fail "OBJ lots: exit $?"
faceInstances=$(awk '$1 == "instances" {print $2}' "$tmp/block.stats")
[ "${faceInstances:-0}" -gt 300 ] || fail "only ${faceInstances:-no} instances for two OBJ lots"
printf 'v 0 0 0\nv 10 0 -10\nv 10 0 0\nv 0 0 -10\nf 1 2 3 4\n' >"$tmp/bow.obj"
expect 2 'bow.obj: face 0: the edge from corner 2 .* crosses' -- "$fgsg" run examples/city.fgsg --lots "$tmp/bow.obj" -o "$tmp/x.glb"
echo "ok: city lots"

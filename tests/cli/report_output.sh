#!/usr/bin/env bash
# fgsg run --report (issue 43): Report(key, value) collected per lot and written as JSON,
# the same bytes from both engines and exactly the values computed by hand: each lot's
# footprint area (Lot.area) against the lots' own areas, its walls' areas, its properties;
# Print's lines on stderr; a failed run leaves an earlier report file as it was.
. "$(dirname "$0")/../reliability/lib.sh"

# Lot A 20 x 10 (200 m2), B 12 x 8 (96 m2), C an L of 10 x 4 + 4 x 6 (64 m2).
cat >"$tmp/lots.geojson" <<'JSON'
{"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},
 "features": [
  {"type": "Feature", "id": "A", "properties": {"height": 12, "use": "shop"}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [20, 0], [20, 10], [0, 10], [0, 0]]]}},
  {"type": "Feature", "id": "B", "properties": {"height": 5, "use": "house"}, "geometry": {"type": "Polygon", "coordinates": [[[30, 0], [42, 0], [42, 8], [30, 8], [30, 0]]]}},
  {"type": "Feature", "id": "C", "properties": {"height": 3, "use": "shop"}, "geometry": {"type": "Polygon", "coordinates": [[[50, 0], [60, 0], [60, 4], [54, 4], [54, 10], [50, 10], [50, 0]]]}}
 ]}
JSON
cat >"$tmp/lots.fgsg" <<'FGSG'
attr height = 0;
attr use = "none";
Lot ~> Report("lot.area", Lot.area) Report("use", use) Report("tall", height > 10)
       Print(use) Extrude(height) Comp("sidefaces"){ Wall };
Wall ~> Report("wall.area", Scope.sx * Scope.sy) W;
FGSG

# Walls: A 12 m high on 20, 10, 20, 10 m; B 5 m on 12, 8, 12, 8; C 3 m on 10, 4, 6, 6, 4, 10.
cat >"$tmp/expected.json" <<'JSON'
{"format":"fgsg-reports","version":1,"starts":[
{"start":0,"lot":{"feature":0,"part":0,"id":"A"},"reports":{"lot.area":{"values":[200],"count":1,"sum":200,"average":200,"min":200,"max":200,"nnz":1},"tall":{"values":[true],"count":1,"sum":1,"average":1,"min":1,"max":1,"nnz":1},"use":{"values":["shop"],"count":1,"strings":{"shop":1}},"wall.area":{"values":[240,120,240,120],"count":4,"sum":720,"average":180,"min":120,"max":240,"nnz":4}}},
{"start":1,"lot":{"feature":1,"part":0,"id":"B"},"reports":{"lot.area":{"values":[96],"count":1,"sum":96,"average":96,"min":96,"max":96,"nnz":1},"tall":{"values":[false],"count":1,"sum":0,"average":0,"min":0,"max":0,"nnz":0},"use":{"values":["house"],"count":1,"strings":{"house":1}},"wall.area":{"values":[60,40,60,40],"count":4,"sum":200,"average":50,"min":40,"max":60,"nnz":4}}},
{"start":2,"lot":{"feature":2,"part":0,"id":"C"},"reports":{"lot.area":{"values":[64],"count":1,"sum":64,"average":64,"min":64,"max":64,"nnz":1},"tall":{"values":[false],"count":1,"sum":0,"average":0,"min":0,"max":0,"nnz":0},"use":{"values":["shop"],"count":1,"strings":{"shop":1}},"wall.area":{"values":[30,12,18,18,12,30],"count":6,"sum":120,"average":20,"min":12,"max":30,"nnz":6}}}
],
"all":{"lot.area":{"values":[200,96,64],"count":3,"sum":360,"average":120,"min":64,"max":200,"nnz":3},"tall":{"values":[true,false,false],"count":3,"sum":1,"average":0.3333333333333333,"min":0,"max":1,"nnz":1},"use":{"values":["shop","house","shop"],"count":3,"strings":{"house":1,"shop":2}},"wall.area":{"values":[240,120,240,120,60,40,60,40,30,12,18,18,12,30],"count":14,"sum":1040,"average":74.28571428571429,"min":12,"max":240,"nnz":14}}}
JSON

for engine in interp jit; do
  "$fgsg" run "$tmp/lots.fgsg" --engine=$engine --lots "$tmp/lots.geojson" -q -o "$tmp/$engine.glb" \
    --report "$tmp/$engine.json" 2>"$tmp/$engine.err" || { cat "$tmp/$engine.err" >&2; fail "$engine: run failed"; }
  diff "$tmp/expected.json" "$tmp/$engine.json" >&2 || fail "$engine: the report is not the expected one"
  # Print: one line per lot, located at the Print.
  [ "$(grep -c ': print: ' "$tmp/$engine.err")" -eq 3 ] || fail "$engine: expected 3 print lines"
  grep -qx "$tmp/lots.fgsg:4:8: print: house" "$tmp/$engine.err" || { cat "$tmp/$engine.err" >&2; fail "$engine: no print line for lot B"; }
done
cmp "$tmp/interp.json" "$tmp/jit.json" || fail "the engines wrote other reports"
# The lots' own areas, from the GeoJSON by the shoelace formula, are the reported ones.
python3 - "$tmp/lots.geojson" "$tmp/jit.json" <<'PY' || fail "reported lot areas differ from the lots' areas"
import json, sys
lots, report = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
for feature, start in zip(lots["features"], report["starts"]):
    ring = feature["geometry"]["coordinates"][0]
    area = abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(ring, ring[1:]))) / 2
    assert start["lot"]["id"] == feature["id"], start
    assert start["reports"]["lot.area"]["values"] == [area], (feature["id"], area, start)
PY

# Without lots: one start shape. Without Report: empty collections.
printf 'Axiom ~> S(2, 3, 0) Report("area", Scope.sx * Scope.sy) A;\n' >"$tmp/one.fgsg"
"$fgsg" run "$tmp/one.fgsg" -q -o "$tmp/one.glb" --report "$tmp/one.json" || fail "one start: run failed"
grep -q '^{"start":0,"reports":{"area":{"values":\[6\],' "$tmp/one.json" || fail "one start: $(cat "$tmp/one.json")"
printf 'Axiom ~> S(2, 3, 0) A;\n' >"$tmp/none.fgsg"
"$fgsg" run "$tmp/none.fgsg" -q -o "$tmp/none.glb" --report "$tmp/none.json" || fail "no reports: run failed"
grep -q '^"all":{}}$' "$tmp/none.json" || fail "no reports: $(cat "$tmp/none.json")"

# Usage errors and failed runs write nothing.
expect 2 "reports are written as JSON" -- "$fgsg" run "$tmp/one.fgsg" -o "$tmp/x.glb" --report "$tmp/r.txt"
cp "$tmp/one.json" "$tmp/keep.json"
printf 'Axiom ~> Report("k", 1) I("missing_asset.obj");\n' >"$tmp/bad.fgsg"
expect 1 "R003" -- "$fgsg" run "$tmp/bad.fgsg" -o "$tmp/bad.glb" --report "$tmp/one.json"
cmp "$tmp/one.json" "$tmp/keep.json" || fail "a failed run changed the report file"
# Report's key must be a string, its value no vector; both are compile errors.
printf 'Axiom ~> Report(1, (1, 2, 3)) A;\n' >"$tmp/types.fgsg"
expect 1 "the key of 'Report' must be a string" -- "$fgsg" check "$tmp/types.fgsg"
grep -q "not a vector" "$tmp/err" || fail "no message for a vector value"
echo "ok: reports"

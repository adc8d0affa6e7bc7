#!/usr/bin/env bash
# Each start shape's glTF node carries its lot's properties, the grammar attrs' values it
# derived with and its reports in `extras`, named after the feature id (issue #45). Three
# lots as in report_output.sh; an independent reader of the .glb's JSON chunk checks the
# names and every value against numbers worked out by hand (the walls' areas, the lots'
# areas), also in a --split-output file and for one axiom with --set.
. "$(dirname "$0")/../reliability/lib.sh"
python=/usr/bin/python3
[ -x "$python" ] || python=python3

# Lot A 20 x 10 (200 m2), B 12 x 8 (96 m2), C an L of 10 x 4 + 4 x 6 (64 m2); C has no id.
cat >"$tmp/lots.geojson" <<'JSON'
{"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},
 "features": [
  {"type": "Feature", "id": "A", "properties": {"height": 12, "use": "shop"}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [20, 0], [20, 10], [0, 10], [0, 0]]]}},
  {"type": "Feature", "id": "B", "properties": {"height": 5, "use": "house", "floors": 2}, "geometry": {"type": "Polygon", "coordinates": [[[30, 0], [42, 0], [42, 8], [30, 8], [30, 0]]]}},
  {"type": "Feature", "properties": {"height": 3}, "geometry": {"type": "Polygon", "coordinates": [[[50, 0], [60, 0], [60, 4], [54, 4], [54, 10], [50, 10], [50, 0]]]}}
 ]}
JSON
cat >"$tmp/lots.fgsg" <<'FGSG'
attr height = 0;
attr use = "none";
attr flat = false;
attr offset = (1, 2, 3);
Lot ~> Report("lot.area", Lot.area) Report("use", use) Report("tall", height > 10)
       Extrude(height) Comp("sidefaces"){ Wall };
Wall ~> Report("wall.area", Scope.sx * Scope.sy) W;
FGSG
"$fgsg" run "$tmp/lots.fgsg" --lots "$tmp/lots.geojson" -q -o "$tmp/lots.glb" --set flat=true \
  --split-output "$tmp/split" 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "run with lots"; }
node "$root/scripts/validate-gltf.js" --strict "$tmp/lots.glb" >"$tmp/validator" 2>&1 ||
  { cat "$tmp/validator" >&2; fail "gltf-validator: errors or warnings"; }

printf 'attr size = 2;\nattr name = "box";\nAxiom ~> S(size, 3, 1) Report("area", Scope.sx * Scope.sy) Report("name", name) I("cube");\n' \
  >"$tmp/one.fgsg"
"$fgsg" run "$tmp/one.fgsg" -q -o "$tmp/one.gltf" --set size=4 || fail "run with one axiom"

"$python" - "$tmp/lots.glb" "$tmp/split" "$tmp/one.gltf" <<'PY' || fail "start nodes' names and extras"
import json, os, struct, sys
glb, split, gltf = sys.argv[1:4]

def document(path):
    data = open(path, "rb").read()
    if path.endswith(".gltf"):
        return json.loads(data)
    assert data[:4] == b"glTF" and struct.unpack_from("<I", data, 16)[0] == 0x4E4F534A, path
    return json.loads(data[20:20 + struct.unpack_from("<I", data, 12)[0]])

def roots(doc):
    return [doc["nodes"][r] for r in doc["scenes"][0]["nodes"]]

def numbers(values):
    n = [float(v) for v in values]
    return {"values": values, "count": len(values), "sum": sum(n), "average": sum(n) / len(n),
            "min": min(n), "max": max(n), "nnz": sum(1 for v in n if v != 0)}

def strings(values):
    return {"values": values, "count": len(values), "strings": {v: values.count(v) for v in set(values)}}

# Walls: A 12 m high on 20, 10, 20, 10 m; B 5 m on 12, 8, 12, 8; C 3 m on 10, 4, 6, 6, 4, 10.
lots = [("A", 12, "shop", 200, [20, 10, 20, 10], {"height": 12, "use": "shop"}),
        ("B", 5, "house", 96, [12, 8, 12, 8], {"height": 5, "use": "house", "floors": 2}),
        ("feature 2", 3, "none", 64, [10, 4, 6, 6, 4, 10], {"height": 3})]
expected = []
for k, (name, height, use, area, walls, properties) in enumerate(lots):
    expected.append({"name": name, "extras": {
        "start": k, "instances": len(walls), "properties": properties,
        "attrs": {"height": height, "use": use, "flat": True, "offset": [1, 2, 3]},
        "reports": {"lot.area": numbers([area]), "use": strings([use]),
                    "tall": dict(numbers([1 if height > 10 else 0]), values=[height > 10]),
                    "wall.area": numbers([w * height for w in walls])}}})

starts = roots(document(glb))
assert [s["name"] for s in starts] == [e["name"] for e in expected], [s["name"] for s in starts]
for s, e in zip(starts, expected):
    assert s["extras"] == e["extras"], (s["name"], s["extras"], e["extras"])
# A file of --split-output carries its start shape's extras alike.
manifest = json.load(open(os.path.join(split, "manifest.json")))
for f, e in zip(manifest["files"], expected):
    [s] = roots(document(os.path.join(split, f["file"])))
    assert s["name"] == e["name"] and s["extras"] == e["extras"], (f["file"], s)
# One axiom: named "axiom", --set's value, no properties.
[s] = roots(document(gltf))
assert s["name"] == "axiom", s["name"]
assert s["extras"] == {"start": 0, "instances": 1, "attrs": {"size": 4, "name": "box"},
                       "reports": {"area": numbers([12]), "name": strings(["box"])}}, s["extras"]
print("ok: names and extras of", len(starts), "lots, their split files and one axiom")
PY
echo "ok"

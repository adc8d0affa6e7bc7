#!/usr/bin/env bash
# The .cga dialect from the command line: examples/cga/building.cga checks clean, runs on
# the 200 GeoJSON lots and on the default lot with the same bytes from the interpreter,
# the JIT and a compiled library (engine_equivalence.sh), and mistakes are located errors.
#   cga_dialect.sh FGSG RUN_LIBRARY ROOT
set -uo pipefail
fgsg=$1
runlib=$2
root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$root" || fail "no root $root"

"$fgsg" check examples/cga/building.cga >"$tmp/check.txt" 2>&1 || { cat "$tmp/check.txt"; fail "building.cga does not check"; }
"$fgsg" run examples/cga/building.cga --lots examples/city/lots.geojson -q -o "$tmp/city.obj" --stats >"$tmp/stats.txt" 2>&1 ||
  { cat "$tmp/stats.txt"; fail "building.cga does not run on the lots"; }
[ -s "$tmp/city.obj" ] || fail "no mesh written"
"$root/tests/engine_equivalence.sh" "$fgsg" "$runlib" "$root" examples/cga/building.cga || fail "engines differ"

# An operation the dialect does not run yet: E800 at its name.
printf '@StartRule\nLot --> extrude(10)\n    reduceGeometry()\n' >"$tmp/taper.cga"
"$fgsg" check "$tmp/taper.cga" >"$tmp/taper.txt" 2>&1 && fail "reduceGeometry passes check"
grep -q "taper.cga:3:5: error\[E800\]: unknown operation 'reduceGeometry' (CityEngine CGA; not supported yet)" "$tmp/taper.txt" ||
  { cat "$tmp/taper.txt"; fail "no located E800 for reduceGeometry"; }
# scatter's body has no selector (issue #44: it runs, tests/cga/scatter); such a body after
# another operation is E018 at its `{`.
printf '@StartRule\nLot --> extrude(10)\n  scatter(surface, 5, uniform) { Tree }\n' >"$tmp/scatter.cga"
"$fgsg" check "$tmp/scatter.cga" >"$tmp/scatter.txt" 2>&1 || { cat "$tmp/scatter.txt"; fail "scatter does not check"; }
printf '@StartRule\nLot --> extrude(10)\n  comp(f) { Tree }\n' >"$tmp/comp.cga"
"$fgsg" check "$tmp/comp.cga" >"$tmp/comp.txt" 2>&1 && fail "comp without selector passes check"
grep -q "comp.cga:3:11: error\[E018\]: 'comp' takes no { operations } body" "$tmp/comp.txt" ||
  { cat "$tmp/comp.txt"; fail "no located E018 for comp"; }
# The same file named .fgsg: the hint to name it .cga.
cp "$tmp/taper.cga" "$tmp/taper.fgsg"
"$fgsg" check "$tmp/taper.fgsg" >"$tmp/hint.txt" 2>&1 && fail "CGA text passes as .fgsg"
grep -q "this looks like CityEngine CGA: name the file .cga" "$tmp/hint.txt" || { cat "$tmp/hint.txt"; fail "no hint"; }
# `dialect cga;` reads a file of another name as CGA.
printf 'dialect cga;\n@StartRule\nLot --> extrude(3)\n' >"$tmp/named.txt"
"$fgsg" run "$tmp/named.txt" -q -o "$tmp/named.obj" || fail "dialect cga; is not read as CGA"
# A missing asset: a warning once, the insert skipped, the rest derived.
printf '@StartRule\nLot --> split(x) { 2 : A }*\nA --> i("nowhere/door.obj") X.\n' >"$tmp/asset.cga"
"$fgsg" run "$tmp/asset.cga" -o "$tmp/asset.obj" >"$tmp/asset.txt" 2>&1 || { cat "$tmp/asset.txt"; fail "a missing asset fails"; }
[ "$(grep -c "W801" "$tmp/asset.txt")" = 1 ] || { cat "$tmp/asset.txt"; fail "W801 not once"; }
# --instances names an asset the rule file found (beside it, in assets/) relative to the
# JSON file's folder, so that the folder moves with its assets (#43/#44); built-in names stay.
mkdir -p "$tmp/proj/rules" "$tmp/proj/assets" "$tmp/proj/out" "$tmp/elsewhere"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$tmp/proj/assets/box.obj"
printf '@StartRule\nLot --> [ i("box.obj") Box. ] i("builtin:cube") Cube.\n' >"$tmp/proj/rules/house.cga"
for engine in interp jit; do
  (cd "$tmp/proj" && "$fgsg" run rules/house.cga --engine $engine -q -o out/h.glb --instances out/h.json) ||
    fail "house.cga does not run ($engine)"
  grep -qF '"assets":["../assets/box.obj","builtin:cube",' "$tmp/proj/out/h.json" ||
    { head -2 "$tmp/proj/out/h.json"; fail "--instances out/h.json: asset not relative to out/ ($engine)"; }
  grep -qF '{"asset":"../assets/box.obj","symbol":"Box",' "$tmp/proj/out/h.json" ||
    { cat "$tmp/proj/out/h.json"; fail "the instance does not name ../assets/box.obj ($engine)"; }
  "$fgsg" run "$tmp/proj/rules/house.cga" --engine $engine -q -o "$tmp/elsewhere/h.glb" --instances "$tmp/elsewhere/h.json" ||
    fail "house.cga does not run with absolute paths ($engine)"
  grep -qF '"assets":["../proj/assets/box.obj",' "$tmp/elsewhere/h.json" ||
    { head -2 "$tmp/elsewhere/h.json"; fail "--instances elsewhere/h.json: asset not relative to elsewhere/ ($engine)"; }
done
# The glTF scene names them the same way, relative to its own folder (extras.asset of an
# instanced mesh, a group's extras.baked); built-in names stay (#43/#44).
printf '@StartRule\nLot --> extrude(3) split(x) { 2 : B }* i("builtin:cube") Cube.\nB --> i("box.obj") Box.\n' >"$tmp/proj/rules/row.cga"
# The assets the file names: "asset=N" per instanced mesh, "baked:NAME=N" per baked one.
gltf_assets() {
  python3 - "$1" <<'PY'
import json, struct, sys
data = open(sys.argv[1], "rb").read()
doc = json.loads(data[20:20 + struct.unpack_from("<I", data, 12)[0]]) if data[:4] == b"glTF" else json.loads(data)
names = []
for node in doc["nodes"]:
    extras = node.get("extras", {})
    if "asset" in extras: names.append("asset=%s:%d" % (extras["asset"], extras["instances"]))
    names += ["baked=%s:%d" % kv for kv in extras.get("baked", {}).items()]
print(" ".join(sorted(names)))
PY
}
for engine in interp jit; do
  (cd "$tmp/proj" && "$fgsg" run rules/row.cga --engine $engine -q --instancing on -o out/row.glb) ||
    fail "row.cga does not run ($engine)"
  got=$(gltf_assets "$tmp/proj/out/row.glb")
  [ "$got" = "asset=../assets/box.obj:10 asset=builtin:cube:1" ] || fail "out/row.glb names: $got ($engine)"
  "$fgsg" run "$tmp/proj/rules/row.cga" --engine $engine -q --instancing on -o "$tmp/elsewhere/row.gltf" ||
    fail "row.cga does not run with absolute paths ($engine)"
  got=$(gltf_assets "$tmp/elsewhere/row.gltf")
  [ "$got" = "asset=../proj/assets/box.obj:10 asset=builtin:cube:1" ] || fail "elsewhere/row.gltf names: $got ($engine)"
  # Baked (--instancing off, grouped): the group's extras.baked counts the same names.
  "$fgsg" run "$tmp/proj/rules/row.cga" --engine $engine -q --instancing off -o "$tmp/elsewhere/baked.glb" ||
    fail "row.cga does not run baked ($engine)"
  got=$(gltf_assets "$tmp/elsewhere/baked.glb")
  [ "$got" = "baked=../proj/assets/box.obj:10 baked=builtin:cube:1" ] || fail "elsewhere/baked.glb names: $got ($engine)"
done

# texture(attr) and i(attr): the attr's default is the file, found when compiling; another
# value from --set or a lot's property stops the derivation with R038 at the first use.
printf '@File\nattr tex = "builtin:cube"\n@StartRule\nLot --> extrude(3)\n  i(tex) Box.\n' >"$tmp/pinned.cga"
for engine in interp jit; do
  "$fgsg" run "$tmp/pinned.cga" --engine $engine -q -o "$tmp/pinned.obj" || fail "i(attr) does not run ($engine)"
  "$fgsg" run "$tmp/pinned.cga" --engine $engine -q -o "$tmp/pinned.obj" --set tex=builtin:cube ||
    fail "i(attr) with --set to its default does not run ($engine)"
  "$fgsg" run "$tmp/pinned.cga" --engine $engine -q -o "$tmp/pinned2.obj" --set tex=other.obj >"$tmp/pinned.txt" 2>&1 &&
    fail "i(attr) with --set tex=other.obj runs ($engine)"
  grep -q "pinned.cga:5:5: error\[R038\]: attr 'tex' = \"other.obj\": this file takes its default \"builtin:cube\"" "$tmp/pinned.txt" ||
    { cat "$tmp/pinned.txt"; fail "no located R038 for --set tex ($engine)"; }
done
# color(r, g, b, a): the colour with a as its material's opacity (corpus 184's top).
for engine in interp jit; do
  "$fgsg" run tests/cga/corpus/184_extrude_up_color_alpha.cga --engine $engine -q -o "$tmp/alpha.glb" ||
    fail "184_extrude_up_color_alpha does not run ($engine)"
  got=$(python3 - "$tmp/alpha.glb" <<'PY'
import json, struct, sys
data = open(sys.argv[1], "rb").read()
doc = json.loads(data[20:20 + struct.unpack_from("<I", data, 12)[0]])
print(" ".join("%s:%g" % (m.get("alphaMode", "OPAQUE"), m["pbrMetallicRoughness"]["baseColorFactor"][3])
               for m in doc["materials"] if m["pbrMetallicRoughness"]["baseColorFactor"][:3] == [1.0, 0.0, 0.0]))
PY
)
  [ "$got" = "BLEND:0.5" ] || fail "color(1, 0, 0, 0.5) gives the material $got ($engine)"
done
echo "cga dialect: ok"

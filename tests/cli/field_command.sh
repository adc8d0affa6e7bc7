#!/usr/bin/env bash
# fgsg field: a grammar's designed field drawn as streamlines and singularities (FGSG
# Fig. 7). The singularities a design puts in are found where it put them and listed
# with their indices; the sketch is a valid glTF (lines included) and a PNG; every
# mistake is a clear error with a non-zero exit.
. "$(dirname "$0")/../reliability/lib.sh"

# A wedge and a trisector designed on a plane: found within 0.1 of where they were put.
cat >"$tmp/design.fgsg" <<'FGSG'
surface plane(10, 10, 48);
field F = design tensor { wedge at (-2, 0, 0) decay 1; trisector at (2, 1, 0) decay 1; regular at (0, -4, 0) angle 0 decay 0.5; };
Axiom ~> I("cube");
FGSG
"$fgsg" field "$tmp/design.fgsg" -o "$tmp/field.glb" --preview "$tmp/field.png" --minor >"$tmp/out" 2>"$tmp/err" ||
  { cat "$tmp/err" >&2; fail "fgsg field failed"; }
grep -q "field F (tensor) on 4608 faces" "$tmp/out" || { cat "$tmp/out" >&2; fail "no summary line"; }
near() {  # near KIND INDEX X Y: a listed singularity of that kind and index within 0.1 of (X, Y)
  awk -v kind="$1," -v index_="$2" -v x="$3" -v y="$4" '
    $1 == kind && $3 == index_ { gsub(/[(),]/, " "); split($0, w, " ");
      dx = w[5] - x; dy = w[6] - y; if (dx * dx + dy * dy < 0.01) found = 1 }
    END { exit !found }' "$tmp/out" || { cat "$tmp/out" >&2; fail "no $1 ($2) near ($3, $4)"; }
}
near wedge +1/2 -2 0
near trisector -1/2 2 1
head -c 8 "$tmp/field.png" | od -An -c | grep -q 'P   N   G' || fail "the preview is not a PNG"
node "$root/scripts/validate-gltf.js" "$tmp/field.glb" >"$tmp/validator" 2>&1 ||
  { cat "$tmp/validator" >&2; fail "gltf-validator rejected the sketch"; }
"$fgsg" field "$tmp/design.fgsg" -o "$tmp/field.obj" >/dev/null 2>&1 || fail "OBJ output failed"
grep -q "^l " "$tmp/field.obj" || fail "the OBJ sketch has no streamline segments"
# The singularities as JSON: the listed ones, with kind, index and position.
"$fgsg" field "$tmp/design.fgsg" --singularities "$tmp/s.json" >/dev/null 2>&1 || fail "--singularities failed"
python3 - "$tmp/s.json" <<'PY' || fail "the singularities JSON is not what was listed"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["field"] == "F"
kinds = sorted((g["kind"], g["index"]) for g in s["singularities"])
assert ("wedge", 0.5) in kinds and ("trisector", -0.5) in kinds, kinds
w = [g for g in s["singularities"] if g["kind"] == "wedge" and abs(g["position"][0] + 2) < 0.1]
assert len(w) == 1 and abs(w[0]["position"][1]) < 0.1, w
PY
expect 2 "written as JSON" -- "$fgsg" field "$tmp/design.fgsg" --singularities "$tmp/s.txt"

# Mistakes: located or named, non-zero.
cp "$root/examples/koch.fgsg" "$tmp/koch.fgsg"
expect 1 "declares no surface" -- "$fgsg" field "$tmp/koch.fgsg" -o "$tmp/x.glb"
printf 'surface plane(4, 4);\nAxiom ~> I("cube");\n' >"$tmp/nofield.fgsg"
expect 1 "declares no field" -- "$fgsg" field "$tmp/nofield.fgsg" -o "$tmp/x.glb"
expect 2 "declares no such field \(F\)" -- "$fgsg" field "$tmp/design.fgsg" --field G -o "$tmp/x.glb"
expect 2 "written as .glb, .obj or .ply" -- "$fgsg" field "$tmp/design.fgsg" -o "$tmp/x.txt"
expect 2 "nothing to write" -- "$fgsg" field "$tmp/design.fgsg"
expect 2 "--seeds" -- "$fgsg" field "$tmp/design.fgsg" --seeds 0 -o "$tmp/x.glb"
printf 'surface "nowhere.off";\nfield F = curvature;\nAxiom ~> I("cube");\n' >"$tmp/nomesh.fgsg"
expect 1 "nomesh.fgsg:1:[0-9]+: error\[R015\]" -- "$fgsg" field "$tmp/nomesh.fgsg" -o "$tmp/x.glb"
[ ! -e "$tmp/x.glb" ] || fail "a failed command wrote its output"
echo "ok: field command"

#!/usr/bin/env bash
# Continuous model synthesis from the command line: every example under
# examples/synthesis/continuous/ runs as its header says, and its output passes the
# independent checker (tests/synthesis/check_continuous.py: a closed 2-manifold whose
# every vertex, edge and face figure occurs in the example) and the glTF validator;
# the checker itself rejects what it must; bad examples and options are refused.
. "$(dirname "$0")/../reliability/lib.sh"
cd "$root" || fail "no source folder"
py=/usr/bin/python3  # numpy
check="$root/tests/synthesis/check_continuous.py"
fixtures="$root/tests/synthesis/fixtures"
validator="$root/scripts/validate-gltf.js"
# No silent skip (#51): the test set-up installs the validator.
[ -d "$root/tools/node/node_modules/gltf-validator" ] ||
  fail "the glTF validator is not installed: run scripts/install-node-packages.sh (scripts/install-deps.sh --test does)"

# The checker can fail: a reflex edge a box lacks, two boxes sharing an edge.
"$py" "$check" "$fixtures/box.obj" "$fixtures/box.obj" >"$tmp/c" || { cat "$tmp/c" >&2; fail "checker: a box fails against itself"; }
"$py" "$check" "$fixtures/box.obj" "$fixtures/l_shape.obj" >/dev/null && fail "checker: an L-shape passes against a box"
"$py" "$check" "$fixtures/box.obj" "$fixtures/two_boxes_touching.obj" >/dev/null && fail "checker: a non-manifold pair passes"

runs=0
for example in examples/synthesis/continuous/*.obj; do
  name=$(basename "$example" .obj)
  while IFS= read -r line; do
    read -r -a args <<< "$line"
    clean=()  # the header's own --preview / -o targets are dropped
    skip=0
    for a in "${args[@]}"; do
      if [ $skip = 1 ]; then skip=0; continue; fi
      case "$a" in --preview|-o) skip=1 ;; *) clean+=("$a") ;; esac
    done
    runs=$((runs + 1))
    out="$tmp/$name-$runs"
    "$fgsg" synth "$example" "${clean[@]}" -o "$out.obj" --stats >"$out.stats" 2>"$tmp/err" ||
      { cat "$tmp/err" >&2; fail "$name: fgsg synth ${clean[*]} failed"; }
    grep -qE '^parts [0-9]+$' "$out.stats" || fail "$name: no stats"
    grep -qx 'parts 0' "$out.stats" && fail "$name: ${clean[*]} made nothing"
    "$py" "$check" "$example" "$out.obj" --max-points 2000 >"$tmp/c" 2>&1 ||
      { cat "$tmp/c" >&2; fail "$name: ${clean[*]}: the output fails the checker"; }
    # The same run again gives the same bytes; as glb it passes the validator.
    "$fgsg" synth "$example" "${clean[@]}" -o "$out-again.obj" 2>/dev/null
    cmp -s "$out.obj" "$out-again.obj" || fail "$name: the same seed gave other bytes"
    "$fgsg" synth "$example" "${clean[@]}" -o "$out.glb" 2>/dev/null || fail "$name: no glb"
    node "$validator" "$out.glb" >"$tmp/v" 2>&1 || { cat "$tmp/v" >&2; fail "$name: gltf-validator reported errors"; }
  done < <(grep -E '^#[[:space:]]+fgsg synth examples/synthesis/continuous/' "$example" |
           sed -E 's#^\#[[:space:]]+fgsg synth examples/synthesis/continuous/[^ ]+##')
done
[ $runs -ge 5 ] || fail "only $runs example runs (each example's header names its command)"

# A glTF example (read through assimp; triangles) has the same figures as the OBJ.
"$fgsg" synth examples/synthesis/continuous/houses.obj --size 8 8 4 --seed 1 -o "$tmp/one_house.glb" 2>/dev/null ||
  fail "no glb house"
"$fgsg" synth "$tmp/one_house.glb" --size 20 20 6 --stats -o "$tmp/from_glb.obj" >"$tmp/glb.stats" 2>"$tmp/err" ||
  { cat "$tmp/err" >&2; fail "a glb example failed"; }
grep -qx 'labels 34' "$tmp/glb.stats" || { cat "$tmp/glb.stats" >&2; fail "the glb house does not have the 34 figures of houses.obj"; }

# Unusable examples and options: located messages, exit 1 or 2.
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\n' >"$tmp/open.obj"
expect 1 "open.obj: error\[E750\]: the solid is not closed: the edge from \(0.000, 0.000, 0.000\) to \(0.000, 1.000, 0.000\) of face 1 has no face on its other side" -- "$fgsg" synth "$tmp/open.obj" --size 4 4 4
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$tmp/flat.obj"
expect 1 "flat.obj: error\[E750\]: a continuous example is a closed solid; this file has 1 face" -- "$fgsg" synth "$tmp/flat.obj" --size 4 4 4
printf 'v 0 0 0\nv 1 0 0\nv 0.309017 0.951057 0\nv 0 0 1\nv 1 0 1\nv 0.309017 0.951057 1\nf 1 3 2\nf 4 5 6\nf 1 2 5 4\nf 2 3 6 5\nf 3 1 4 6\n' >"$tmp/skew.obj"
expect 1 "skew.obj: error\[E750\]: face 1's normal \(0.000, 0.000, -1.000\)|skew.obj: error\[E750\]: face [0-9]+'s normal .* is not within 0.1 degrees of an integer direction" -- "$fgsg" synth "$tmp/skew.obj" --size 4 4 4
expect 1 "error" -- "$fgsg" synth "$tmp/missing.obj" --size 4 4 4
expect 2 "--size X Y Z is required" -- "$fgsg" synth examples/synthesis/continuous/box.obj
expect 2 "--fixed-width needs A,B,C:N" -- "$fgsg" synth examples/synthesis/continuous/box.obj --size 4 4 4 --fixed-width 1,0:2
expect 2 "--on-ground and --floating exclude each other" -- "$fgsg" synth examples/synthesis/continuous/box.obj --size 4 4 4 --on-ground --floating
expect 2 "--fill needs a number from 0 to 1" -- "$fgsg" synth examples/synthesis/continuous/box.obj --size 4 4 4 --fill 2
expect 1 "E751.*which no face of the example has" -- "$fgsg" synth examples/synthesis/continuous/box.obj --size 4 4 4 --fixed-width 1,1,0:2
# Standing on the ground the bridge keeps its soffit (the header's run above); a box too
# low for a width of 5 leaves room for nothing: E752, nothing written.
expect 1 "bridge.obj: error\[E752\]: the synthesized model is empty \(0 parts\), nothing was written: --fixed-width 0,1,0:5 makes every object 5 plane spacings across" -- "$fgsg" synth examples/synthesis/continuous/bridge.obj --size 8 8 3 --fixed-width 0,1,0:5 -o "$tmp/low_bridge.obj"
[ -e "$tmp/low_bridge.obj" ] && fail "an empty bridge model was written"
expect 1 "E751.*more than 8000000 vertices" -- "$fgsg" synth examples/synthesis/continuous/houses.obj --size 4000 4000 4000
# In a grammar: sizes and the parts' symbol checked.
mkdir -p "$tmp/g"
cp examples/synthesis/continuous/houses.obj "$tmp/g/"
printf 'axiom: S(8, 4, 8) A;\nA ~> Synthesize("houses.obj", 1, 4, 8, "H");\nH ~> Comp("f"){ vertical: W | aslant: R };\nW ~> I("cube");\nR ~> I("cube");\n' >"$tmp/g/one.fgsg"
expect 1 "R012.*at least 2 plane spacings" -- "$fgsg" run "$tmp/g/one.fgsg" -o "$tmp/g/one.glb"
printf 'axiom: S(8, 4, 8) A;\nA ~> Synthesize("houses.obj", 8, 4, 8, "Hose");\nH ~> I("cube");\n' >"$tmp/g/typo.fgsg"
expect 1 "typo.fgsg:2:.*E064.*'Hose' is no symbol of this grammar" -- "$fgsg" check "$tmp/g/typo.fgsg"
printf 'axiom: S(8, 4, 8) A;\nA ~> Synthesize("houses.obj", 8, 4, 8, "H");\nH ~> Comp("f"){ vertical: W | aslant: R };\nW ~> I("cube");\nR ~> I("cube");\n' >"$tmp/g/ok.fgsg"
"$fgsg" run "$tmp/g/ok.fgsg" -o "$tmp/g/ok.glb" --stats >"$tmp/g/stats" 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "a grammar synthesizing houses failed"; }
grep -qE "^instances [1-9]" "$tmp/g/stats" || fail "a grammar synthesizing houses placed nothing"
echo "ok: continuous synthesis ($runs example runs)"

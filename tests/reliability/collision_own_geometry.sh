#!/usr/bin/env bash
# A CGA leaf's own geometry is an obstacle like any instance (#42 R1): under `collision
# all` a leaf that is neither a whole box nor a unit square (the fuzzer's Line grammar,
# a triangle lot) ran into "R900 internal error ... asset '(own geometry)' not found" in
# both engines while `check` said ok. Now it derives, the engines agree, and the leaf
# stops what runs into it.
. "$(dirname "$0")/lib.sh"

# ok COMMAND...: COMMAND ends (within 60 s) with exit code 0; stdout in $tmp/out.
ok() {
  timeout 60 "$@" >"$tmp/out" 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "'$*': exit $?"; }
}

g="$inputs/collision_line_own_geometry.fgsg"
ok "$fgsg" check "$g"
grep -q "ok" "$tmp/out" || fail "check did not say ok"
for engine in jit interp; do
  ok "$fgsg" run "$g" --engine=$engine -q --stats -o "$tmp/line.$engine.obj"
  grep -qx "instances 3" "$tmp/out" || { cat "$tmp/out" >&2; fail "line grammar ($engine): not 3 instances"; }
done
cmp -s "$tmp/line.jit.obj" "$tmp/line.interp.obj" || fail "line grammar: the engines wrote other bytes"

# A triangle lot, then a cube through it and one beside it: the first cube collides with
# the lot's triangle (cull: the rest of the production goes; omit: only that cube).
write() {
  cat >"$tmp/$1.fgsg" <<G
$2
axiom: A;
A ~> [ Footprint(0, 0, 4, 0, 0, 4) Lot ] T(0.5, -0.5, 0.5) S(1, 1, 1) I("cube") T(5, 0, 0) I("cube");
G
}
write none ""
write cull "collision all;"
write omit "collision all omit;"
for case in none:3 cull:1 omit:2; do
  name=${case%%:*} count=${case##*:}
  for engine in jit interp; do
    ok "$fgsg" run "$tmp/$name.fgsg" --engine=$engine -q --stats -o "$tmp/$name.$engine.obj"
    grep -qx "instances $count" "$tmp/out" || { cat "$tmp/out" >&2; fail "$name ($engine): expected $count instances"; }
  done
  cmp -s "$tmp/$name.jit.obj" "$tmp/$name.interp.obj" || fail "$name: the engines wrote other bytes"
done
exit 0

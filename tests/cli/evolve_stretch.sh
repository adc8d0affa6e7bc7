#!/usr/bin/env bash
# fgsg evolve --surface --stats (#46, Chan & Hui §6.4): the stretch of the pattern's cells
# on a mesh, against values worked out by hand on boxes (runtime/evolve/ornament_stretch.h
# and tests/unit/evolve/ornament_stretch_test.cpp derive them), and --max-stretch: no
# emitted cell beyond it, a counted warning for those left out; bad values refused (2).
. "$(dirname "$0")/../reliability/lib.sh"
tiles="$root/examples/assets/ornament_tiles.json"
lsys='{ABAA.ABBA.A}'  # the paper's Fig. 2: generation 0 is 1 x 1 cells, generation 1 is 2 x 2

# box X Y Z FILE: an axis-aligned box from the origin, as OFF.
box() {
  { echo OFF; echo "8 6 0"
    for i in 0 1 2 3 4 5 6 7; do
      echo "$([ $((i & 1)) = 1 ] && echo "$1" || echo 0) $([ $((i & 2)) = 2 ] && echo "$2" || echo 0) $([ $((i & 4)) = 4 ] && echo "$3" || echo 0)"
    done
    echo "4 0 2 3 1"; echo "4 4 5 7 6"; echo "4 0 1 5 4"; echo "4 2 6 7 3"; echo "4 0 4 6 2"; echo "4 1 3 7 5"
  } >"$4"
}
stat() { awk -v k="$1" '$1 == k { print $2 }' "$2"; }
box 8 8 8 "$tmp/cube.off"
box 8 8 2.4 "$tmp/flat.off"
box 8 1.3 1.4 "$tmp/thin.off"

# A cube on the lattice: every cell unstretched.
"$fgsg" evolve "$tiles" -q --lsystem "$lsys" --generation 1 --surface "$tmp/cube.off" --stats >"$tmp/cube" ||
  fail "cube: exit $?"
[ "$(stat stretch.max "$tmp/cube")" = 1.000000 ] || fail "cube: stretch.max $(stat stretch.max "$tmp/cube")"
[ "$(stat surface.cells "$tmp/cube")" = 1536 ] || fail "cube: $(stat surface.cells "$tmp/cube") cells, expected 384 x 4"

# The flat box's rim: sqrt(1 + 0.4^2) at one cell a face-let (28 of 192 face-lets), 1.4 at two.
"$fgsg" evolve "$tiles" -q --lsystem "$lsys" --generation 0 --surface "$tmp/flat.off" --stats >"$tmp/flat1" ||
  fail "flat box: exit $?"
[ "$(stat surface.cells "$tmp/flat1")" = 192 ] || fail "flat box: $(stat surface.cells "$tmp/flat1") cells"
[ "$(stat stretch.median "$tmp/flat1")" = 1.000000 ] || fail "flat box: median $(stat stretch.median "$tmp/flat1")"
[ "$(stat stretch.p95 "$tmp/flat1")" = 1.077033 ] || fail "flat box: p95 $(stat stretch.p95 "$tmp/flat1")"
[ "$(stat stretch.max "$tmp/flat1")" = 1.077033 ] || fail "flat box: max $(stat stretch.max "$tmp/flat1")"
"$fgsg" evolve "$tiles" -q --lsystem "$lsys" --generation 1 --surface "$tmp/flat.off" --stats >"$tmp/flat2" ||
  fail "flat box, 2 x 2: exit $?"
[ "$(stat stretch.max "$tmp/flat2")" = 1.400000 ] || fail "flat box, 2 x 2: max $(stat stretch.max "$tmp/flat2")"

# The thin box: unbounded, cells stretched past 1.5; bounded by 1.5, none emitted past it,
# and the cells left out are counted on stderr.
"$fgsg" evolve "$tiles" -q --lsystem "$lsys" --generation 1 --surface "$tmp/thin.off" --max-stretch 0 --stats \
  >"$tmp/free" 2>"$tmp/free.err" || fail "thin box, no limit: exit $?"
awk -v m="$(stat stretch.max "$tmp/free")" 'BEGIN { exit !(m > 1.5) }' || fail "thin box: max $(stat stretch.max "$tmp/free") <= 1.5"
[ "$(stat stretch.left_out_cells "$tmp/free")" = 0 ] || fail "thin box, no limit: cells left out"
[ ! -s "$tmp/free.err" ] || fail "thin box, no limit: a warning: $(cat "$tmp/free.err")"
"$fgsg" evolve "$tiles" -q --lsystem "$lsys" --generation 1 --surface "$tmp/thin.off" --max-stretch 1.5 --stats \
  >"$tmp/bound" 2>"$tmp/bound.err" || fail "thin box, 1.5: exit $?"
left=$(stat stretch.left_out_cells "$tmp/bound")
awk -v m="$(stat stretch.emitted_max "$tmp/bound")" 'BEGIN { exit !(m <= 1.5) }' ||
  fail "thin box, 1.5: emitted max $(stat stretch.emitted_max "$tmp/bound")"
[ "$left" -gt 0 ] || fail "thin box, 1.5: no cell left out"
grep -q "warning: $left of $(stat surface.cells "$tmp/bound") cells were left out, stretched beyond --max-stretch 1.5" \
  "$tmp/bound.err" || fail "thin box, 1.5: warning '$(cat "$tmp/bound.err")'"
[ "$(stat surface.triangles "$tmp/bound")" -lt "$(stat surface.triangles "$tmp/free")" ] ||
  fail "thin box, 1.5: as many triangles as without the limit"

# Bad values: usage errors naming the problem.
for bad in 0.5 -2 inf abc; do
  expect 2 "max-stretch" -- "$fgsg" evolve "$tiles" --lsystem "$lsys" --surface "$tmp/cube.off" --max-stretch "$bad"
done
expect 2 "--stats reports the ornament on a surface" -- "$fgsg" evolve "$tiles" --lsystem "$lsys" --stats
expect 2 "resolution" -- "$fgsg" evolve "$tiles" --lsystem "$lsys" --surface "$tmp/cube.off" --resolution 0
expect 1 "missing.off" -- "$fgsg" evolve "$tiles" --lsystem "$lsys" --surface "$tmp/missing.off"
echo "evolve --surface --stats: ok"

#!/usr/bin/env bash
# Points far from the surface (a design element at 1e308, --start 1e160) are located on
# the surface, never off the mesh: squared distances no longer overflow.
. "$(dirname "$0")/lib.sh"

for engine in jit interp; do
  expect 0 "wrote" -- "$fgsg" run "$inputs/14_design_element_far_point.fgsg" --engine=$engine -o "$tmp/a.obj"
  expect 0 "wrote" -- "$fgsg" run "$inputs/15_start_far_point.fgsg" --engine=$engine --start 1e160,0,0 -o "$tmp/b.$engine.obj"
done
cmp -s "$tmp/b.jit.obj" "$tmp/b.interp.obj" || fail "--start 1e160: the engines differ"
# From far along +X the closest point of the torus(2, 0.6) is its outer rim at x = 2.6.
"$fgsg" run "$inputs/15_start_far_point.fgsg" --start 1e160,0,0 -q --instances "$tmp/far.json" -o "$tmp/far.obj" || fail "far start"
"$fgsg" run "$inputs/15_start_far_point.fgsg" --start 100,0,0 -q --instances "$tmp/near.json" -o "$tmp/near.obj" || fail "near start"
cmp -s "$tmp/far.json" "$tmp/near.json" || fail "--start 1e160,0,0 and 100,0,0 start at other points"
grep -q '2\.6' "$tmp/near.json" || { cat "$tmp/near.json" >&2; fail "the start is not on the outer rim (x = 2.6)"; }
echo "far points: ok"

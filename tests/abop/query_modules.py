#!/usr/bin/env python3
"""ABOP's and lpfg's query modules ?P ?H ?U ?L (issue 48; Prusinkiewicz, James and Mech
1994), each against values worked out by hand from the turtle's convention in
docs/language.md (start at the origin, H = +Y, L = -X, U = +Z; + turns H towards L, &
turns H towards -U):

* the four queries after F(1) +(90) F(2) &(90) F(3), read by the next step through a left
  context and drawn as segments starting at the values (@M);
* the two-argument form inside and after a branch;
* a guard on ?P's y that stops growth: the segment count.
Interpreter and JIT alike (the compiled library: tests/cases/lsystem_query_modules).
    query_modules.py FGSG REPO_ROOT
"""
import sys
import tempfile

from lsystem_reference import same_segments, segments_3d


def four_queries(fgsg, folder, engine):
    text = ('derive parallel 1;\nturtle segments "lines";\n'
            "axiom: F(1) +(90) F(2) &(90) F(3) ?P(0, 0, 0) ?H(0, 0, 0) ?U(0, 0, 0) ?L(0, 0, 0) A;\n"
            "?P(x, y, z) ?H(hx, hy, hz) ?U(ux, uy, uz) ?L(lx, ly, lz) < A ->\n"
            "  @M(x, y, z) F(1) @M(hx, hy, hz) F(1) @M(ux, uy, uz) F(1) @M(lx, ly, lz) F(1);\n")
    # By hand: F(1) ends at (0, 1, 0); +(90) turns H = (0, 1, 0) towards L = (-1, 0, 0):
    # H = (-1, 0, 0), L = (0, -1, 0) (H x L = U = (0, 0, 1) still). F(2) ends at (-2, 1, 0).
    # &(90) turns H towards -U: H = (0, 0, -1), U = the old H = (-1, 0, 0), L unchanged
    # (H x L = (0, 0, -1) x (0, -1, 0) = (-1, 0, 0) = U). F(3) ends at (-2, 1, -3).
    # So after the axiom ?P = (-2, 1, -3), ?H = (0, 0, -1), ?U = (-1, 0, 0), ?L = (0, -1, 0);
    # A's successor draws a unit segment along H = (0, 0, -1) from each.
    axiom = [((0, 0, 0), (0, 1, 0)), ((0, 1, 0), (-2, 1, 0)), ((-2, 1, 0), (-2, 1, -3))]
    starts = [(-2, 1, -3), (0, 0, -1), (-1, 0, 0), (0, -1, 0)]
    want = axiom + [(p, (p[0], p[1], p[2] - 1)) for p in starts]
    same_segments(segments_3d(fgsg, folder, "four", text, engine), want, "?P ?H ?U ?L after F +(90) F &(90) F", engine)


def in_branches(fgsg, folder, engine):
    text = ('derive parallel 1;\nturtle segments "lines";\n'
            "axiom: F(1) [ +(90) F(2) ?P(0, 0) B ] F(1) ?P(0, 0) B;\n"
            "?P(x, y) < B -> @M(x, y, 0) F(0.5);\n")
    # By hand: the branch turns left at (0, 1, 0) and ends at (-2, 1, 0) heading -X; the
    # main axis, restored by ']' to (0, 1, 0) heading +Y, ends at (0, 2, 0).
    want = [((0, 0, 0), (0, 1, 0)), ((0, 1, 0), (-2, 1, 0)), ((0, 1, 0), (0, 2, 0)),
            ((-2, 1, 0), (-2.5, 1, 0)), ((0, 2, 0), (0, 2.5, 0))]
    same_segments(segments_3d(fgsg, folder, "branches", text, engine), want, "?P(x, y) in and after a branch", engine)


def guard_stops_growth(fgsg, folder, engine):
    text = ('derive parallel 10;\nturtle segments "lines";\n'
            "axiom: A ?P(0, 0, 0);\nA > ?P(x, y, z) : y < 3.5 -> F(1) A;\n")
    # By hand: ?P follows A, so it holds the tip. It reads y = 0 after the axiom, then
    # 1, 2, 3 after steps 1-3: A grows at steps 1-4; at step 5 y = 4 and A stops, so 4
    # segments up to (0, 4, 0) of the 10 steps' 10.
    want = [((0, k, 0), (0, k + 1, 0)) for k in range(4)]
    same_segments(segments_3d(fgsg, folder, "guard", text, engine), want, "a guard on ?P's y stops growth at 4 segments",
                  engine)


def main():
    fgsg = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        for engine in ("interp", "jit"):
            four_queries(fgsg, folder, engine)
            in_branches(fgsg, folder, engine)
            guard_stops_growth(fgsg, folder, engine)


main()

#!/usr/bin/env python3
"""The environmental query ?E of open L-systems (issue 48; Mech and Prusinkiewicz 1996),
answered by the grammar's first field at the surface point closest to the turtle, each
against values worked out by hand (docs/language.md, the turtle: the turtle starts at the
origin heading +Y; + turns H towards -X, ^ towards +Z):

* a constant vector field (a file, every vertex (0.6, 0.8, 0)) read after F(1);
* a single regular design element, direction (0.6, 0.8, 0), decay 1e-12: the same field;
* a linear scalar field read on a vertex, inside a face and above the plane;
* a linear vector field (-y, x, 0) (a file) read inside a face and on an edge;
* a centre (vortex) element at the origin read at (0, 2, 0) and (-2, 0, 0): a
  counter-clockwise field of length e^(-2 d), along -X and -Y there;
* a guard on ?E that stops growth: the segment count.

A value is checked by a guard to the stated tolerance (the rule that draws fires only when
every component is within it), and drawn as a segment starting at it (@M). Interpreter and
JIT alike (the compiled library: tests/cases/lsystem_env_query).
    env_query.py FGSG REPO_ROOT
"""
import math
import os
import sys
import tempfile

from lsystem_reference import same_segments, segments_3d

PLANE = "surface plane(8, 8, 8);\n"  # vertices at the whole numbers from -4 to 4


def within(names, values, tolerances):
    """A guard: each name within its tolerance of its value."""
    return " && ".join("abs(%s - (%r)) < %r" % (n, v, t) for n, v, t in zip(names, values, tolerances))


def vector_read(fgsg, folder, engine, name, field, moves, want, tolerance, what, plane=PLANE):
    """After MOVES from the origin ?E(x, y, z) must be WANT within TOLERANCE (a number, or
    one per component). Drawn: the moves' segments and a unit segment along +Y from WANT."""
    if not isinstance(tolerance, tuple):
        tolerance = (tolerance,) * 3
    text = ('derive parallel 1;\nturtle segments "lines";\n' + plane + field +
            "axiom: %s ?E(0, 0, 0) A;\n" % moves +
            "?E(x, y, z) < A : %s -> @M(x, y, z) @R(0, 1, 0, 0, 0, 1) F(1);\n" %
            within("xyz", want, tolerance))
    got = segments_3d(fgsg, folder, name, text, engine)
    # The guard's segment: from the value along +Y (the OBJ keeps 8 digits).
    near = lambda s: all(abs(s[k] - want[k]) < tolerance[k] + 1e-6 for k in range(3)) and \
        abs(s[3] - s[0]) < 1e-6 and abs(s[4] - s[1] - 1) < 1e-6 and abs(s[5] - s[2]) < 1e-6
    if not any(near(s) for s in got):
        raise SystemExit("FAIL: %s (%s): no segment from %s (the guard within %s failed); segments %s"
                         % (what, engine, want, tolerance, got))
    print("ok: %s (%s)" % (what, engine))


def constant_fields(fgsg, folder, engine):
    path = os.path.join(folder, "constant.vfield")
    with open(path, "w") as f:
        f.write("fgsg-field 1 vector 81 world\n" + "0.6 0.8 0\n" * 81)
    # By hand: every vertex holds (0.6, 0.8, 0), so the field is that everywhere; after
    # F(1) the turtle stands at (0, 1, 0), a vertex.
    vector_read(fgsg, folder, engine, "constfile", 'field V = vector("%s");\n' % path, "F(1)",
                (0.6, 0.8, 0.0), 1e-9, "?E of a constant vector field (file) after F(1)")
    # A regular element: s e^(-d rho) times its direction, with d = 1e-12 and rho <= 2:
    # (0.6, 0.8, 0) within 3e-12.
    design = "field W = design vector { regular at (0, 0, 0) direction (0.6, 0.8, 0) decay 1e-12; };\n"
    vector_read(fgsg, folder, engine, "regular", design, "F(1)", (0.6, 0.8, 0.0), 1e-9,
                "?E of a single regular element after F(1)")


def scalar_field(fgsg, folder, engine):
    # S = 0.5 x + 2 y + 3, linear: exact on vertices and inside faces (linear per triangle).
    # F(1) +(90) F(2): (0, 1) then 2 along -X: (-2, 1), a vertex: S = -1 + 2 + 3 = 4.
    # F(1) +(90) F(0.75): (-0.75, 1), on an edge: S = -0.375 + 2 + 3 = 4.625.
    # F(1) ^(90) F(2): (0, 1, 2), above the plane; the closest point (0, 1, 0): S = 5.
    # F(1.5) -(90) F(0.25): (0.25, 1.5), inside a face: S = 0.125 + 3 + 3 = 6.125.
    for name, moves, want in (("vertex", "F(1) +(90) F(2)", 4.0), ("edge", "F(1) +(90) F(0.75)", 4.625),
                              ("above", "F(1) ^(90) F(2)", 5.0), ("face", "F(1.5) -(90) F(0.25)", 6.125)):
        text = ('derive parallel 1;\nturtle segments "lines";\n' + PLANE +
                "field S = scalar(0.5 * x + 2 * y + 3);\n"
                "axiom: %s ?E(0) A;\n" % moves +
                "?E(s) < A : abs(s - %r) < 1e-9 -> @M(s, 0, 5) F(1);\n" % want)
        got = segments_3d(fgsg, folder, "scalar" + name, text, engine)
        if not any(abs(s[0] - want) < 1e-6 and abs(s[2] - 5) < 1e-9 for s in got):
            raise SystemExit("FAIL: ?E(s) of S = 0.5x + 2y + 3 after %s (%s): want %r; segments %s"
                             % (moves, engine, want, got))
        print("ok: ?E(s) of a linear scalar field after %s = %r (%s)" % (moves, want, engine))


def rotation_field(fgsg, folder, engine):
    # The linear field v(x, y) = (-y, x, 0) (a rigid rotation about +Z), written at the
    # vertices of plane(8, 8, 8) (row by row from (-4, -4), x fastest): linear per
    # triangle, so exact everywhere on the flat grid (docs/fields.md). F(1.5) -(90)
    # F(0.25) ends at (0.25, 1.5), inside a face: v = (-1.5, 0.25, 0). F(1) +(90) F(2.5)
    # ends at (-2.5, 1), on an edge: v = (-1, -2.5, 0).
    path = os.path.join(folder, "rotation.vfield")
    with open(path, "w") as f:
        f.write("fgsg-field 1 vector 81 world\n")
        for j in range(9):
            for i in range(9):
                x, y = -4 + i, -4 + j
                f.write("%r %r 0\n" % (float(-y), float(x)))
    field = 'field R = vector("%s");\n' % path
    vector_read(fgsg, folder, engine, "rotface", field, "F(1.5) -(90) F(0.25)", (-1.5, 0.25, 0.0), 1e-9,
                "?E of the linear field (-y, x) inside a face, at (0.25, 1.5)")
    vector_read(fgsg, folder, engine, "rotedge", field, "F(1) +(90) F(2.5)", (-1.0, -2.5, 0.0), 1e-9,
                "?E of the linear field (-y, x) on an edge, at (-2.5, 1)")


def centre_element(fgsg, folder, engine):
    # A centre at the origin turns counter-clockwise about +Z: at distance rho its vector
    # is e^(-d rho) (Z x r / rho). With d = 0.5, at (0, 2, 0): e^(-1) (-1, 0, 0); at
    # (-2, 0, 0) (+(90) F(2)): e^(-1) (0, -1, 0). The direction is exact (1e-9); the
    # length carries the heat method's geodesic distance on a grid of spacing 0.25
    # (docs/fields.md), measured 2.2 % long here: within 3 %.
    design = "field C = design vector { centre at (0, 0, 0) decay 0.5; };\n"
    fine = "surface plane(16, 16, 64);\n"
    e = math.exp(-1)
    vector_read(fgsg, folder, engine, "centre1", design, "F(2)", (-e, 0.0, 0.0), (0.03 * e, 1e-9, 1e-9),
                "?E of a centre element at (0, 2, 0)", fine)
    vector_read(fgsg, folder, engine, "centre2", design, "+(90) F(2)", (0.0, -e, 0.0), (1e-9, 0.03 * e, 1e-9),
                "?E of a centre element at (-2, 0, 0)", fine)


def guard_stops_growth(fgsg, folder, engine):
    text = ('derive parallel 10;\nturtle segments "lines";\nsurface plane(20, 20, 20);\n'
            "field S = scalar(2 * y + 1);\n"
            "axiom: A ?E(0);\nA > ?E(s) : s < 7.5 -> F(1) A;\n")
    # By hand: ?E follows A, so it reads S at the tip: 1 after the axiom, then 3, 5, 7
    # after steps 1-3: A grows at steps 1-4; after step 4 the tip is at y = 4, S = 9, and
    # A stops: 4 segments up to (0, 4, 0) of the 10 steps' 10.
    want = [((0, k, 0), (0, k + 1, 0)) for k in range(4)]
    same_segments(segments_3d(fgsg, folder, "guard", text, engine), want, "a guard on ?E stops growth at 4 segments", engine,
                  tolerance=1e-6)


def main():
    fgsg = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        for engine in ("interp", "jit"):
            constant_fields(fgsg, folder, engine)
            scalar_field(fgsg, folder, engine)
            rotation_field(fgsg, folder, engine)
            centre_element(fgsg, folder, engine)
            guard_stops_growth(fgsg, folder, engine)


main()

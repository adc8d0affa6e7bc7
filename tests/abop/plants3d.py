#!/usr/bin/env python3
"""ABOP's three-dimensional plants, derived by an independent rewriter and drawn by an
independent 3D turtle written from L-Py's conventions (lpy_turtle.py), compared segment by segment (in 3D) and polygon by polygon with
what fgsg writes: Fig. 1.25, the bush (examples/abop/fig1_25.fgsg), and Fig. 1.26, the
plant with flowers (examples/abop/fig1_26.fgsg), at the book's n and one step less. The
grammars are written here again from the book, not read from the examples.
    plants3d.py FGSG REPO_ROOT
"""
import math
import os
import struct
import sys
import tempfile

from lpy_turtle import draw
from lsystem_reference import fgsg_obj, unmatched

# Fig. 1.25 (ABOP p. 26), as fgsg spells it: symbols one character each, `.` after each
# f of the leaf (the book's f records a polygon vertex), S written Seg (here: S).
BUSH = (7, 22.5, "A", {
    "A": "[&FL!A]/////'[&FL!A]///////'[&FL!A]",
    "F": "S/////F",
    "S": "FL",
    "L": "['''^^{-f.+f.+f.-|-f.+f.+f.}]",
})

# Fig. 1.26 (ABOP p. 27): the plant with flowers, with its multi-letter symbols renamed
# to one letter: plant P, internode I, seg S, leaf L, flower W, pedicel D, wedge E.
FLOWERS = (5, 18.0, "P", {
    "P": "I+[P+W]--//[--L]I[++L]-[PW]++PW",
    "I": "FS[//&&L][//^^L]FS",
    "S": "SFS",
    "L": "['{+f.-f.f.-f.+|+f.-f.f.-f.}]",
    "W": "[&&&D'/E////E////E////E////E]",
    "D": "FF",
    "E": "['^F][{&&&&-f.+f.|-f.+f.}]",
})


def derive(axiom, rules, n):
    s = axiom
    for _ in range(n):
        s = "".join(rules.get(c, c) for c in s)
    return s


def turtle3d(s, angle):
    """L-Py's turtle (lpy_turtle.draw): F draws a unit segment, f moves; `.` inside
    `{ }` records a vertex. Returns (segments as (x0, y0, z0, x1, y1, z1), polygons as
    lists of (x, y, z)), in fgsg's axes."""
    return draw(s, angle)


def as_float32(v):
    return tuple(struct.unpack("3f", struct.pack("3f", *v)))


def fan_triangles(polygons, min_area=1e-12):
    """The triangles fgsg fills a polygon with: a fan from its first vertex, without those
    whose area is below the assembler's threshold, measured as it does on the vertices
    stored as 32-bit floats (a leaf's collinear vertices make some triangles that only
    rounding gives an area)."""
    out = []
    for poly in polygons:
        for k in range(1, len(poly) - 1):
            a, b, c = as_float32(poly[0]), as_float32(poly[k]), as_float32(poly[k + 1])
            u = [y - x for x, y in zip(a, b)]
            v = [y - x for x, y in zip(a, c)]
            cross = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
            if 0.5 * math.sqrt(sum(x * x for x in cross)) >= min_area:
                out.append(a + b + c)
    return out


def check(fgsg, grammar, n, string, angle, folder):
    segs, polygons = turtle3d(string, angle)
    got = fgsg_obj(fgsg, grammar, n, folder, dims=3)
    for what, want, have in (("segments", segs, got["l"]), ("triangles", fan_triangles(polygons), got["f"])):
        missing = unmatched(want, have)
        if len(want) != len(have) or missing:
            raise SystemExit("FAIL: %s n=%d: fgsg has %d %s, the reference %d (%d of the reference's missing)"
                             % (os.path.basename(grammar), n, len(have), what, len(want), missing))
        print("ok: %s n=%d, %d %s" % (os.path.basename(grammar), n, len(want), what))


def main():
    fgsg, root = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as folder:
        for name, (n, angle, axiom, rules) in (("fig1_25", BUSH), ("fig1_26", FLOWERS)):
            grammar = os.path.join(root, "examples/abop/%s.fgsg" % name)
            for steps in (n - 1, n):
                check(fgsg, grammar, steps, derive(axiom, rules, steps), angle, folder)


main()

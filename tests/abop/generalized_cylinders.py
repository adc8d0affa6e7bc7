#!/usr/bin/env python3
"""lpfg's and L-Py's generalized cylinders (@Gs, @Gc(n), @Ge(n); issue 48) as fgsg writes
them to OBJ, against values worked out here from the cpfg tutorial's definition (cubic
Hermite pieces between control points, end tangents along the turtle's headings, each
1.2 times the chord; rings across the curve, radius half the turtle's width):

* a straight tube @Gs F(1) @Gc(4) F(1) @Ge(4), width 0.3, 6 sides: (8 + 1) x 6 vertices,
  every one at 0.15 from the axis, the rings at the Hermite heights;
* a 90-degree bend: the middle ring's centre at the Hermite midpoint, the last ring's at
  the turtle's end point, every ring's vertices at the radius from its centre;
* a turn right round and a zero-length piece: finite numbers only;
* an L-system whose rules write cylinders in branches: its vertex and triangle counts by
  hand, and the interpreter's and the JIT's OBJ files byte for byte the same.
    generalized_cylinders.py FGSG REPO_ROOT
"""
import math
import os
import subprocess
import sys
import tempfile


def fail(message):
    raise SystemExit("FAIL: " + message)


def run(fgsg, folder, name, text, engine):
    """fgsg's OBJ for TEXT: (its bytes, its vertices, its triangles as vertex indices)."""
    grammar = os.path.join(folder, name + ".fgsg")
    with open(grammar, "w") as f:
        f.write(text)
    out = os.path.join(folder, "%s-%s.obj" % (name, engine))
    subprocess.run([fgsg, "run", grammar, "-o", out, "--quiet", "--engine=" + engine], check=True)
    vertices, faces = [], []
    with open(out, "rb") as f:
        data = f.read()
    for line in data.decode().splitlines():
        part = line.split()
        if part and part[0] == "v":
            vertices.append(tuple(float(c) for c in part[1:4]))
        elif part and part[0] == "f":
            faces.append(tuple(int(c.split("/")[0]) - 1 for c in part[1:]))
    return data, vertices, faces


def hermite(p0, m0, p1, m1, t):
    h = (2 * t ** 3 - 3 * t ** 2 + 1, t ** 3 - 2 * t ** 2 + t, -2 * t ** 3 + 3 * t ** 2, t ** 3 - t ** 2)
    return tuple(h[0] * a + h[1] * b + h[2] * c + h[3] * d for a, b, c, d in zip(p0, m0, p1, m1))


def dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def centre(ring):
    return tuple(sum(v[k] for v in ring) / len(ring) for k in range(3))


def straight(fgsg, folder, engine):
    text = "derive parallel 0;\nturtle width 0.3 sides 6;\naxiom: @Gs F(1) @Gc(4) F(1) @Ge(4);\n"
    _, vs, fs = run(fgsg, folder, "straight", text, engine)
    if len(vs) != 9 * 6 or len(fs) != 8 * 6 * 2:
        fail("straight tube (%s): %d vertices, %d triangles; expected 54 and 96" % (engine, len(vs), len(fs)))
    heights = set()
    for k in range(2):
        for s in range(5):
            heights.add(round(k + hermite((0,), (1.2,), (1,), (1.2,), s / 4.0)[0], 9))
    for x, y, z in vs:
        if abs(math.hypot(x, z) - 0.15) > 1e-6 or min(abs(y - h) for h in heights) > 1e-6:
            fail("straight tube (%s): vertex (%g, %g, %g) off the radius 0.15 or the heights %s"
                 % (engine, x, y, z, sorted(heights)))
    print("ok: a straight tube, 9 rings of 6 at radius 0.15 (%s)" % engine)


def bend(fgsg, folder, engine):
    text = "derive parallel 0;\nturtle width 0.2 sides 8;\naxiom: @Gs F(1) @Gc +(90) F(1) @Ge(8);\n"
    _, vs, fs = run(fgsg, folder, "bend", text, engine)
    rings = [vs[8 * r:8 * r + 8] for r in range(len(vs) // 8)]
    if len(vs) != 10 * 8:
        fail("bend (%s): %d vertices, expected 80" % (engine, len(vs)))
    # + turns the heading from +Y towards the left, -X: the second piece ends at (-1, 1, 0).
    k = 1.2  # the chord from (0, 1, 0) to (-1, 1, 0) is 1
    middle = hermite((0, 1, 0), (0, k, 0), (-1, 1, 0), (-k, 0, 0), 0.5)
    for r, ring in enumerate(rings):
        c = centre(ring)
        if any(abs(dist(v, c) - 0.1) > 1e-6 for v in ring):
            fail("bend (%s): ring %d not at radius 0.1 from its centre %s" % (engine, r, c))
    if dist(centre(rings[5]), middle) > 1e-6 or dist(centre(rings[-1]), (-1, 1, 0)) > 1e-6:
        fail("bend (%s): middle ring at %s (expected %s), last at %s (expected the turtle's end (-1, 1, 0))"
             % (engine, centre(rings[5]), middle, centre(rings[-1])))
    print("ok: a 90-degree bend through the Hermite midpoint %s to the turtle's end (%s)"
          % (tuple(round(c, 6) for c in middle), engine))


def degenerate(fgsg, folder, engine):
    for i, axiom in enumerate(("@Gs F(1) @Gc(2) | F(1) @Ge(8)", "@Gs F(0) @Gc F(1) @Ge(3)")):
        data, vs, _ = run(fgsg, folder, "degenerate%d" % i, "derive parallel 0;\naxiom: %s;\n" % axiom, engine)
        if not vs or b"nan" in data.lower() or b"inf" in data.lower():
            fail("%s (%s): %d vertices, or a number that is not finite" % (axiom, engine, len(vs)))
    print("ok: a turn right round and a zero-length piece stay finite (%s)" % engine)


PLANT = """derive parallel 3;
turtle angle 30 width 0.1 sides 5;
axiom: A(1);
A(k) -> @Gs F(1) @Gc(2) [ + B(k) ] F(1) @Ge(3) A(k + 1);
B(k) -> @Gc F(0.5) F(0.5) @Ge;
"""


def plant(fgsg, folder):
    # After 3 steps: three stems @Gs F @Gc(2) [ + B ] F @Ge(3) of 1 + 2 + 3 rings, each branch
    # (B rewritten in steps 2 and 3: two of them) L-Py's @Gc F F @Ge of 3 rings; the last A
    # and the youngest B draw nothing. Vertices 5 a ring, 2 x 5 triangles a strip.
    stems, branches = 3, 2
    rings = stems * 6 + branches * 3
    strips = stems * 5 + branches * 2
    out = {}
    for engine in ("interp", "jit"):
        data, vs, fs = run(fgsg, folder, "plant", PLANT, engine)
        if len(vs) != 5 * rings or len(fs) != 10 * strips:
            fail("plant (%s): %d vertices, %d triangles; expected %d and %d"
                 % (engine, len(vs), len(fs), 5 * rings, 10 * strips))
        out[engine] = data
    if out["interp"] != out["jit"]:
        fail("plant: the interpreter's and the JIT's OBJ files differ")
    print("ok: tubes in an L-system's branches, %d rings; interpreter = JIT byte for byte" % rings)


def main():
    fgsg = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        for engine in ("interp", "jit"):
            straight(fgsg, folder, engine)
            bend(fgsg, folder, engine)
            degenerate(fgsg, folder, engine)
        plant(fgsg, folder)


main()

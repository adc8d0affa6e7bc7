#!/usr/bin/env python3
"""Tropism (ABOP eq. 2.4, `@Tp(x, y, z)`, `@Ts(e)`): after each F the heading H turns
about H x T by e |H x T| radians. fgsg's segments, vertex by vertex, against two
independent computations:

* in the plane of H and T the bend is one angle: the angle between H and T goes from
  theta to theta - e sin(theta) at each segment, so a branch starting at right angles
  to T ends at sum_k (sin theta_k, cos theta_k) (in the frame of T) - no 3D rotation at
  all;
* L-Py's turtle (lpy_turtle.py: Rodrigues' rotation about H x T after each F) for
  branches in 3D, per-segment elasticities from parameters and [ ] restoring T and e.
    tropism.py FGSG REPO_ROOT
"""
import math
import os
import sys
import tempfile

from lpy_turtle import draw
from lsystem_reference import fgsg_obj, unmatched


def planar(e, n, theta0):
    """The end points of n unit segments bent towards T = (0, -1) (fgsg's axes: T = -Y)
    from a heading at theta0 from T, turning towards +X: (x, y) after each segment."""
    theta, x, y, out = theta0, 0.0, 0.0, []
    for _ in range(n):
        x, y = x + math.sin(theta), y - math.cos(theta)
        out.append((x, y))
        theta -= e * math.sin(theta)
    return out


def run(fgsg, folder, name, text):
    grammar = os.path.join(folder, name + ".fgsg")
    with open(grammar, "w") as f:
        f.write(text)
    return fgsg_obj(fgsg, grammar, 1, folder, dims=3)["l"]


def compare(what, want, got, tolerance=1e-5):
    missing = unmatched(want, got, tolerance)
    if len(want) != len(got) or missing:
        raise SystemExit("FAIL: %s: fgsg has %d segments, the reference %d (%d of the reference's missing)\n"
                         "fgsg: %s\nreference: %s" % (what, len(got), len(want), missing, got, want))
    print("ok: %s, %d segments" % (what, len(want)))


def main():
    fgsg = sys.argv[1]
    header = 'attr n = 1;\nderive parallel n;\nturtle segments "lines";\n'
    with tempfile.TemporaryDirectory() as folder:
        # A horizontal branch (heading +X after -(90)) bending down under gravity T = -Y.
        e, n = 0.2, 12
        got = run(fgsg, folder, "planar", header + "axiom: @Tp(0, -1, 0) @Ts(%g) -(90) X;\nX -> %s;\n"
                  % (e, " ".join(["F"] * n)))
        ends = planar(e, n, math.pi / 2)
        starts = [(0.0, 0.0)] + ends[:-1]
        compare("a horizontal branch under gravity, the planar recurrence",
                [(a[0], a[1], 0.0, b[0], b[1], 0.0) for a, b in zip(starts, ends)], got)
        # The same with the default T (ABOP's gravitropism, (0, -1, 0)).
        got = run(fgsg, folder, "default", header + "axiom: @Ts(%g) -(90) X;\nX -> %s;\n" % (e, " ".join(["F"] * n)))
        compare("the default tropism vector is (0, -1, 0)",
                [(a[0], a[1], 0.0, b[0], b[1], 0.0) for a, b in zip(starts, ends)], got)

        # 3D: a branch pitched and rolled, bent towards an oblique T, against L-Py's turtle.
        modules = [("@Tp", [0.3, -1.0, 0.5]), ("@Ts", [0.27]), ("/", [30.0]), ("&", [70.0])] + [("F", [])] * 10
        got = run(fgsg, folder, "oblique", header + "axiom: @Tp(0.3, -1, 0.5) @Ts(0.27) /(30) &(70) X;\nX -> %s;\n"
                  % " ".join(["F"] * 10))
        compare("an oblique tropism in 3D, L-Py's turtle", draw(modules)[0], got)

        # Per-segment elasticity from parameters, and [ ] restoring T and e.
        steps = 8
        text = header.replace("attr n = 1", "attr n = %d" % steps) + (
            "axiom: @Tp(1, 0, 0) &(60) A(0);\n"
            "A(k) -> @Ts(0.05 * k) F [ +(40) @Tp(0, 0, 1) @Ts(0.4) F F ] A(k + 1);\n")
        grammar = os.path.join(folder, "param.fgsg")
        with open(grammar, "w") as f:
            f.write(text)
        got = fgsg_obj(fgsg, grammar, steps, folder, dims=3)["l"]
        modules = [("@Tp", [1.0, 0.0, 0.0]), ("&", [60.0])]
        for k in range(steps):
            modules += [("@Ts", [0.05 * k]), ("F", []), ("[", []), ("+", [40.0]), ("@Tp", [0.0, 0.0, 1.0]),
                        ("@Ts", [0.4]), ("F", []), ("F", []), ("]", [])]
        compare("per-segment elasticity from a parameter, [ ] restoring T and e", draw(modules)[0], got)

        # ABOP Fig. 2.8a (examples/abop/fig2_8a.fgsg), rewritten here from the book.
        fig2_8a(fgsg, os.path.join(sys.argv[2], "examples/abop/fig2_8a.fgsg"))


def fig2_8a(fgsg, grammar):
    """ABOP Fig. 2.8a at n = 4 and 6: an independent parametric rewriter, L-Py's turtle
    with T = (0, -1, 0) and e = 0.22; segments compared as (start, end, width) from fgsg's
    instances (a segment's box is centred on its path)."""
    import json
    import subprocess
    d1, d2, a, lr, vr = 94.74, 132.63, 18.95, 1.109, 1.732

    def successor(symbol, args):
        if symbol == "A":
            out = [("!", [vr]), ("F", [50.0])]
            for k, turn in enumerate(([], [("/", [d1])], [("/", [d2])])):
                out += turn + [("[", []), ("&", [a]), ("F", [50.0]), ("A", []), ("]", [])]
            return out
        if symbol == "F":
            return [("F", [args[0] * lr])]
        if symbol == "!":
            return [("!", [args[0] * vr])]
        return None

    from lpy_turtle import Turtle, TURNS, to_fgsg
    for n in (4, 6):
        s = [("@Tp", [0.0, -1.0, 0.0]), ("@Ts", [0.22]), ("!", [1.0]), ("F", [200.0]), ("/", [45.0]), ("A", [])]
        for _ in range(n):
            out = []
            for symbol, args in s:
                out.extend(successor(symbol, args) or [(symbol, args)])
            s = out
        t, stack, want = Turtle(), [], []
        t.tropism, t.elasticity = (0.0, 0.0, -1.0), 0.22  # the axiom's @Tp(0, -1, 0) in L-Py's world
        for symbol, args in s[2:]:
            if symbol == "F":
                p, q = t.forward(args[0])
                want.append(to_fgsg(p) + to_fgsg(q) + (t.width,))
                t.bend()
            elif symbol == "!":
                t.width = args[0]
            elif symbol in TURNS:
                t.turn(symbol, args[0])
            elif symbol == "[":
                stack.append(t.state())
            elif symbol == "]":
                t.restore(stack.pop())
        with tempfile.TemporaryDirectory() as folder:
            out, listing = os.path.join(folder, "tree.glb"), os.path.join(folder, "tree.json")
            subprocess.run([fgsg, "run", grammar, "-o", out, "--instances", listing, "--set", "n=%d" % n, "--quiet"],
                           check=True)
            with open(listing) as f:
                data = json.load(f)
        got = []
        for inst in data["instances"]:
            if inst["symbol"] != "F":
                continue
            m = inst["transform"]  # column-major
            point = lambda u, v, w: [m[r] * u + m[4 + r] * v + m[8 + r] * w + m[12 + r] for r in range(3)]
            got.append(tuple(point(0.5, 0, 0.5) + point(0.5, 1, 0.5) + [math.sqrt(m[0] ** 2 + m[1] ** 2 + m[2] ** 2)]))
        compare("ABOP Fig. 2.8a n=%d (start, end, width)" % n, want, got, tolerance=1e-6 * 200 * 1.109 ** n)


main()

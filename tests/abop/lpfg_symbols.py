#!/usr/bin/env python3
"""lpfg's and ABOP's symbols read by fgsg (issue 48), each against values computed here:

* ABOP's / cpfg's `*` (no context, no condition) in a rule's head, while `*` in an
  expression stays a product: segments from an independent rewriter and L-Py's turtle;
* lpfg's `,` (the previous colour of the palette) after `;` steps: each segment's colour
  from the palette by the index the steps give;
* `@o(r)`: a disc of radius r centred on the turtle across the heading (PlantGL's turtle
  draws its disc in the plane of L and U): its box's centre, its normal and its size, after
  a pitch and a roll, from L-Py's turtle.
Interpreter and JIT alike.
    lpfg_symbols.py FGSG REPO_ROOT
"""
import json
import math
import os
import sys
import tempfile

from lpy_turtle import Turtle, draw, to_fgsg
from lsystem_reference import fgsg_obj, unmatched, write_grammar


def run(fgsg, folder, name, text, engine, listing=False):
    """fgsg's segments for TEXT as (x0, y0, z0, x1, y1, z1) tuples, or with LISTING its
    `--instances` listing."""
    grammar = write_grammar(folder, name, text)
    if not listing:
        return fgsg_obj(fgsg, grammar, None, folder, dims=3, engine=engine)["l"]
    out = os.path.join(folder, "%s-%s.json" % (name, engine))
    fgsg_obj(fgsg, grammar, None, folder, dims=3, engine=engine, extra=["--instances", out])
    with open(out) as f:
        return json.load(f)


def fail(message):
    raise SystemExit("FAIL: " + message)


def wildcards(fgsg, folder, engine):
    # `* < A > * : * -> ...` is `A -> ...`; `B < A > *` a left context alone; `k * 2` a product.
    text = ('derive parallel 3;\nturtle angle 90 segments "lines";\naxiom: B A(1);\n'
            "* < A(k) > * : * -> F(k * 2) + A(k + 1);\nB < A(k) > * -> F(k) A(k);\n")
    got = run(fgsg, folder, "wildcards", text, engine)
    # B < A holds only where A follows B directly: at step 1 (axiom B A(1)); afterwards A
    # follows F and turns, which are commands, skipped by context matching: B < A holds
    # at every step, so the context rule (specific) wins each time.
    s = [("B", []), ("A", [1.0])]
    for _ in range(3):
        out = []
        for sym, args in s:
            out += [("F", args), ("A", args)] if sym == "A" else [(sym, args)]
        s = out
    want = draw(s, angle=90.0)[0]
    if len(want) != len(got) or unmatched(want, got, 1e-6):
        fail("wildcards (%s): fgsg %s, reference %s" % (engine, got, want))
    # Without the left context the `*` rule alone: k * 2 grows.
    text = ('derive parallel 3;\nturtle angle 90 segments "lines";\naxiom: A(1);\n'
            "* < A(k) > * : * -> F(k * 2) + A(k + 1);\n")
    got = run(fgsg, folder, "wildcards2", text, engine)
    s = [("F", [2.0]), ("+", []), ("F", [4.0]), ("+", []), ("F", [6.0]), ("+", [])]
    want = draw(s, angle=90.0)[0]
    if len(want) != len(got) or unmatched(want, got, 1e-6):
        fail("`*` as no context (%s): fgsg %s, reference %s" % (engine, got, want))
    print("ok: ABOP's * in rule heads, a * b in expressions (%s)" % engine)


def colours(fgsg, folder, engine):
    palette = ["#ff0000", "#00ff00", "#0000ff"]
    text = ('derive parallel 0;\nturtle segments "lines" colors "%s";\n'
            "axiom: ; F ; F ; F , F , F ,(3) F , F , , , F;\n" % " ".join(palette))
    data = run(fgsg, folder, "colours", text, engine, listing=True)
    got = [tuple(round(c, 4) for c in inst["color"][:3]) for inst in data["instances"]]
    # Indices after each step: 1 2 3 2 1 3 2 then 0 (not below 0): the default colour, the
    # colour an F takes before any step.
    index = [1, 2, 3, 2, 1, 3, 2]
    rgb = lambda h: tuple(round(int(h[k:k + 2], 16) / 255.0, 4) for k in (1, 3, 5))
    want = [rgb(palette[i - 1]) for i in index]
    plain = run(fgsg, folder, "plain", 'derive parallel 0;\nturtle segments "lines";\naxiom: F;\n', engine,
                listing=True)
    want.append(tuple(round(c, 4) for c in plain["instances"][0]["color"][:3]))
    if got != want:
        fail("lpfg's , (%s): colours %s, expected %s" % (engine, got, want))
    print("ok: lpfg's , steps back through the palette, not below 0 (%s)" % engine)


def circle(fgsg, folder, engine):
    text = 'derive parallel 0;\nturtle segments "lines";\naxiom: F(2) &(30) /(50) F(1) @o(0.4) F(1) @o;\n'
    data = run(fgsg, folder, "circle", text, engine, listing=True)
    discs = [i for i in data["instances"] if i["asset"] == "disc"]
    t = Turtle()
    t.forward(2.0)
    t.turn("&", 30.0)
    t.turn("/", 50.0)
    t.forward(1.0)
    first = (to_fgsg(t.P), to_fgsg(t.H), 0.4)
    t.forward(1.0)
    second = (to_fgsg(t.P), to_fgsg(t.H), 0.05)  # half the default width 0.1
    if len(discs) != 2:
        fail("@o (%s): %d discs, expected 2" % (engine, len(discs)))
    for inst, (centre, heading, r) in zip(discs, (first, second)):
        m = inst["transform"]  # column-major 4x4: the unit box onto the disc's box
        col = lambda k: [m[4 * k + j] for j in range(3)]
        at = [m[12 + j] + 0.5 * (m[j] + m[4 + j]) for j in range(3)]  # the middle of the box's z = 0 face
        sizes = [math.sqrt(sum(c * c for c in col(k))) for k in range(3)]
        normal = [c / sizes[2] for c in col(2)]
        ok = all(abs(a - b) < 1e-5 for a, b in zip(at, centre)) and all(abs(s - 2 * r) < 1e-6 for s in sizes)
        # The disc's plane is across the heading: its box's z axis is -H.
        ok = ok and all(abs(a + b) < 1e-6 for a, b in zip(normal, heading))
        if not ok or inst["symbol"] != "F":
            fail("@o (%s): disc %s, expected centre %s, normal -%s, radius %g" % (engine, inst, centre, heading, r))
    print("ok: @o centred on the turtle across its heading, radius given and default (%s)" % engine)


def main():
    fgsg = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        for engine in ("interp", "jit"):
            wildcards(fgsg, folder, engine)
            colours(fgsg, folder, engine)
            circle(fgsg, folder, engine)


main()

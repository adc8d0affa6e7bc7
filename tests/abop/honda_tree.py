#!/usr/bin/env python3
"""ABOP Fig. 2.6a, Honda's monopodial tree: a parametric L-system with `$`, derived by an
independent rewriter and drawn by an independent 3D turtle written from L-Py's
conventions (lpy_turtle.py), compared segment by segment
(start, end and width) with the segments fgsg places for examples/abop/fig2_6a.fgsg
(`--instances`), at the book's n = 10 and at n = 6. The productions are written here
again from the book, not read from the example.
    honda_tree.py FGSG REPO_ROOT
"""
import json
import math
import os
import subprocess
import sys
import tempfile

from lpy_turtle import TURNS, Turtle, to_fgsg
from lsystem_reference import unmatched

R1, R2, A0, A2, D, WR = 0.9, 0.6, 45.0, 45.0, 137.5, 0.707


def successor(symbol, args):
    """The productions of Fig. 2.6a; None for a module no production rewrites."""
    if symbol not in "ABC":
        return None
    l, w = args
    if symbol == "A":
        return [("!", [w]), ("F", [l]), ("[", []), ("&", [A0]), ("B", [l * R2, w * WR]), ("]", []),
                ("/", [D]), ("A", [l * R1, w * WR])]
    turn, other = ("-", "C") if symbol == "B" else ("+", "B")
    return [("!", [w]), ("F", [l]), ("[", []), (turn, [A2]), ("$", []), (other, [l * R2, w * WR]), ("]", []),
            (other, [l * R1, w * WR])]


def derive(n):
    s = [("A", [1.0, 0.1])]
    for _ in range(n):
        out = []
        for symbol, args in s:
            out.extend(successor(symbol, args) or [(symbol, args)])
        s = out
    return s


def turtle(modules):
    """L-Py's turtle (lpy_turtle.Turtle, `$` its RollToVert). Returns the segments F(l)
    draws as (start, end, width) in fgsg's axes, flattened to 7 numbers."""
    t, stack, segs = Turtle(), [], []
    t.width = 0.1
    for symbol, args in modules:
        if symbol == "F":
            a, b = t.forward(args[0])
            segs.append(to_fgsg(a) + to_fgsg(b) + (t.width,))
        elif symbol == "!":
            t.width = args[0]
        elif symbol in TURNS:
            t.turn(symbol, args[0] if args else 0.0)
        elif symbol == "[":
            stack.append(t.state())
        elif symbol == "]":
            t.restore(stack.pop())
    return segs


def fgsg_segments(fgsg, grammar, n, folder):
    """The segments fgsg places (its F instances) as (start, end, width): a segment's box
    is centred on the path, so its axis runs from the box's (0.5, 0, 0.5) to (0.5, 1, 0.5)."""
    out, listing = os.path.join(folder, "tree.glb"), os.path.join(folder, "tree.json")
    subprocess.run([fgsg, "run", grammar, "-o", out, "--instances", listing, "--set", "n=%d" % n, "--quiet"],
                   check=True)
    with open(listing) as f:
        data = json.load(f)
    segs = []
    for inst in data["instances"]:
        if inst["symbol"] != "F":
            continue
        t = inst["transform"]  # column-major
        point = lambda u, v, w: [t[r] * u + t[4 + r] * v + t[8 + r] * w + t[12 + r] for r in range(3)]
        width = math.sqrt(t[0] ** 2 + t[1] ** 2 + t[2] ** 2)
        segs.append(tuple(point(0.5, 0, 0.5) + point(0.5, 1, 0.5) + [width]))
    return segs


def main():
    fgsg, root = sys.argv[1], sys.argv[2]
    grammar = os.path.join(root, "examples/abop/fig2_6a.fgsg")
    with tempfile.TemporaryDirectory() as folder:
        for n in (6, 10):
            want = turtle(derive(n))
            got = fgsg_segments(fgsg, grammar, n, folder)
            missing = unmatched(want, got, tolerance=1e-6)
            if len(want) != len(got) or missing:
                raise SystemExit("FAIL: fig2_6a.fgsg n=%d: fgsg has %d segments, the reference %d (%d of the "
                                 "reference's missing)" % (n, len(got), len(want), missing))
            print("ok: fig2_6a.fgsg n=%d, %d segments" % (n, len(want)))


main()

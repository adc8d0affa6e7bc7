#!/usr/bin/env python3
"""The sense of each 3D turtle turn, as L-Py and lpfg turn: short strings of one or two
turns and segments, drawn by fgsg and by an independent turtle written from L-Py's
conventions (lpy_turtle.py), compared vertex by vertex; and the few end points the
conventions fix without any turtle (`&(90) F` ends at -U, i.e. (0, 0, -1) in fgsg's axes).
    turtle_sense.py FGSG REPO_ROOT
"""
import math
import os
import sys
import tempfile

from lpy_turtle import draw
from lsystem_reference import fgsg_obj, unmatched

# (successor, fixed end point of its last segment or None), drawn with angle 90 (or the
# given angles) from the turtle's start: H = +Y, L = -X, U = +Z.
CASES = [
    ("F", (0, 1, 0)),
    ("+ F", (-1, 0, 0)),        # turn left: towards L = -X
    ("- F", (1, 0, 0)),
    ("& F", (0, 0, -1)),        # pitch down: towards -U
    ("^ F", (0, 0, 1)),
    ("/ + F", (0, 0, 1)),       # roll right: L turns towards U = +Z, and + heads there
    ("\\ + F", (0, 0, -1)),
    ("| F", (0, -1, 0)),
    ("& $ + F", None),          # heading horizontal after &: $ levels L
    ("/(30) &(40) F +(50) ^(20) F \\(70) -(10) F", None),
    ("[ &(45) F ] /(137.5) [ &(45) F ] /(137.5) [ &(45) F ] F", None),
    ("&(30) /(60) $ F ^(25) F", None),
    # lpfg's @M (move to a point) and @R (set the heading and up vectors).
    ("F @M(2,0,0) F", (2, 1, 0)),
    ("@R(1,0,0,0,0,1) F + F", (1, 1, 0)),   # H = +X, U = +Z, so L = U x H = +Y
    ("&(30) @R(0,0,-1,0,1,0) F / + F", None),
]


def parse(successor):
    """The successor as (symbol, [args]) modules."""
    out = []
    for word in successor.split():
        if "(" in word:
            symbol, arg = word[:-1].split("(")
            out.append((symbol, [float(a) for a in arg.split(",")]))
        else:
            out.append((word, []))
    return out


def spheres(fgsg, folder):
    """lpfg's @O(r): a sphere of radius r (default half the width) centred on the turtle:
    the sphere instances' centres and sizes from `--instances`."""
    import json
    import subprocess
    grammar = os.path.join(folder, "spheres.fgsg")
    with open(grammar, "w") as f:
        f.write("attr n = 1;\nderive parallel n;\nturtle width 0.4;\naxiom: X;\nX -> F @O(0.5) &(90) F @O;\n")
    listing = os.path.join(folder, "spheres.json")
    subprocess.run([fgsg, "run", grammar, "-o", os.path.join(folder, "s.glb"), "--instances", listing, "-q"],
                   check=True)
    with open(listing) as f:
        data = json.load(f)
    got = []
    for inst in data["instances"]:
        if inst["asset"] != "sphere":
            continue
        m = inst["transform"]  # column-major, the unit box's corner and axes
        centre = [m[12 + r] + 0.5 * (m[r] + m[4 + r] + m[8 + r]) for r in range(3)]
        got.append((round(centre[0], 9), round(centre[1], 9), round(centre[2], 9),
                    round(math.sqrt(m[0] ** 2 + m[1] ** 2 + m[2] ** 2) / 2, 9)))
    want = [(0.0, 1.0, 0.0, 0.5), (0.0, 1.0, -1.0, 0.2)]  # &(90) heads to -U = -Z; width 0.4
    if got != want:
        print("FAIL: @O: fgsg's spheres (centre, radius) %s, expected %s" % (got, want))
        return 1
    print("ok: @O: 2 spheres centred on the turtle")
    return 0


def main():
    fgsg = sys.argv[1]
    failed = 0
    with tempfile.TemporaryDirectory() as folder:
        for k, (successor, end) in enumerate(CASES):
            grammar = os.path.join(folder, "sense%d.fgsg" % k)
            with open(grammar, "w") as f:
                f.write('attr n = 1;\nderive parallel n;\nturtle angle 90 segments "lines";\n'
                        "axiom: X;\nX -> %s;\n" % successor)
            want, _ = draw(parse(successor), 90.0)
            got = fgsg_obj(fgsg, grammar, 1, folder, dims=3)["l"]
            missing = unmatched(want, got, tolerance=1e-5)
            if end is not None and any(abs(a - b) > 1e-9 for a, b in zip(want[-1][3:], end)):
                raise SystemExit("the reference turtle itself ends %s at %s, not %s" % (successor, want[-1][3:], end))
            if len(want) != len(got) or missing:
                print("FAIL: X -> %s: fgsg draws %s, L-Py's turtle %s" % (successor, got, want))
                failed += 1
            else:
                print("ok: X -> %s: %d segments" % (successor, len(want)))
        failed += spheres(fgsg, folder)
    if failed:
        raise SystemExit("FAIL: %d of %d turtle strings differ from L-Py's turtle" % (failed, len(CASES)))


main()

#!/usr/bin/env python3
"""ABOP Fig. 1.31a, derived by an independent implementation and compared with fgsg.

This script rewrites the context-sensitive 2L-system of examples/abop/fig1_31a.fgsg the
way The Algorithmic Beauty of Plants (section 1.8) defines it -- every module rewritten
in parallel; a context symbol found by stepping over #ignore'd symbols and whole
branches ([...]) on the left and over #ignore'd symbols and branches on the right;
productions for the turn symbols -- then draws the string with a 2D turtle, and checks
that `fgsg run` with `turtle segments "lines"` writes exactly those segments (OBJ `l`
lines), for several numbers of steps.
    context_plant.py FGSG REPO_ROOT
"""
import math
import os
import subprocess
import sys
import tempfile

IGNORE = set("+-F")
RULES = {  # (left, pred, right) -> successor; the book's 0 and 1 are a and b
    ("a", "a", "a"): "a",
    ("a", "a", "b"): "b[+FbFb]",
    ("a", "b", "a"): "b",
    ("a", "b", "b"): "b",
    ("b", "a", "a"): "a",
    ("b", "a", "b"): "bFb",
    ("b", "b", "a"): "b",
    ("b", "b", "b"): "a",
}
TURNS = {"+": "-", "-": "+"}


def left_context(s, i):
    """The symbol ABOP's left context sees before s[i], or None."""
    j = i - 1
    while j >= 0:
        c = s[j]
        if c == "]":  # step over the whole branch
            depth = 0
            while j >= 0:
                if s[j] == "]":
                    depth += 1
                elif s[j] == "[":
                    depth -= 1
                    if depth == 0:
                        break
                j -= 1
            j -= 1
        elif c == "[" or c in IGNORE:  # out of the branch into its parent; ignored symbols
            j -= 1
        else:
            return c
    return None


def right_context(s, i):
    """The symbol ABOP's right context sees after s[i], or None."""
    j = i + 1
    while j < len(s):
        c = s[j]
        if c == "[":  # step over the whole branch
            depth = 0
            while j < len(s):
                if s[j] == "[":
                    depth += 1
                elif s[j] == "]":
                    depth -= 1
                    if depth == 0:
                        break
                j += 1
            j += 1
        elif c == "]":  # the end of this branch: no right context
            return None
        elif c in IGNORE:
            j += 1
        else:
            return c
    return None


def step(s):
    out = []
    for i, c in enumerate(s):
        if c in TURNS:
            out.append(TURNS[c])
        elif c in "ab":
            key = (left_context(s, i), c, right_context(s, i))
            out.append(RULES.get(key, c))
        else:
            out.append(c)
    return "".join(out)


def segments(s, angle):
    """F as unit segments; heading +Y; '+' turns left (Y towards -X) about +Z."""
    x, y, h = 0.0, 0.0, 90.0
    stack, segs = [], []
    for c in s:
        if c == "F":
            nx, ny = x + math.cos(math.radians(h)), y + math.sin(math.radians(h))
            segs.append((x, y, nx, ny))
            x, y = nx, ny
        elif c == "+":
            h += angle
        elif c == "-":
            h -= angle
        elif c == "[":
            stack.append((x, y, h))
        elif c == "]":
            x, y, h = stack.pop()
    return segs


def unmatched(want, got, tolerance=1e-3):
    """The segments of `want` with no segment of `got` within `tolerance` (each used once);
    fgsg writes 32-bit floats, so coordinates agree to about 1e-6 of the plant's size."""
    cells = {}
    cell = lambda v: tuple(int(math.floor(c / 0.01)) for c in v[:2])
    for g in got:
        cells.setdefault(cell(g), []).append(g)
    missing = 0
    for w in want:
        cx, cy = cell(w)
        found = None
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for g in cells.get((cx + dx, cy + dy), []):
                    if all(abs(a - b) <= tolerance for a, b in zip(w, g)):
                        found = (cx + dx, cy + dy), g
                        break
                if found:
                    break
            if found:
                break
        if found:
            cells[found[0]].remove(found[1])
        else:
            missing += 1
    return missing


def fgsg_segments(fgsg, grammar, n, folder):
    out = os.path.join(folder, "plant%d.obj" % n)
    subprocess.run([fgsg, "run", grammar, "-o", out, "--set", "n=%d" % n, "--quiet"], check=True)
    vertices, segs = [], []
    with open(out) as f:
        for line in f:
            part = line.split()
            if part and part[0] == "v":
                vertices.append((float(part[1]), float(part[2])))
            elif part and part[0] == "l":
                a, b = vertices[int(part[1]) - 1], vertices[int(part[2]) - 1]
                segs.append((a[0], a[1], b[0], b[1]))
    return segs


def main():
    fgsg, root = sys.argv[1], sys.argv[2]
    grammar = os.path.join(root, "examples/abop/fig1_31a.fgsg")
    s = "FbFbFb"
    strings = [s]
    for _ in range(30):
        s = step(s)
        strings.append(s)
    with tempfile.TemporaryDirectory() as folder:
        for n in (1, 5, 12, 30):
            want = segments(strings[n], 22.5)
            got = fgsg_segments(fgsg, grammar, n, folder)
            missing = unmatched(want, got)
            if len(want) != len(got) or missing:
                sys.exit("FAIL: n=%d: fgsg drew %d segments, the reference %d (%d of the reference's missing)"
                         % (n, len(got), len(want), missing))
            print("ok: n=%d, %d segments" % (n, len(want)))
    # The signal has reached the apex and flowered by step 30 (a plant, not a stick).
    if strings[30].count("[") < 20:
        sys.exit("FAIL: the reference plant has only %d branches" % strings[30].count("["))


main()

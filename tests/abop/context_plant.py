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
import os
import sys
import tempfile

from lsystem_reference import check, left_context, right_context

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


def step(s):
    out = []
    for i, c in enumerate(s):
        if c in TURNS:
            out.append(TURNS[c])
        elif c in "ab":
            skipped = lambda m: m in IGNORE
            key = (left_context(s, i, skipped), c, right_context(s, i, skipped))
            out.append(RULES.get(key, c))
        else:
            out.append(c)
    return "".join(out)


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
            check(fgsg, grammar, n, strings[n], 22.5, folder)
    # The signal has reached the apex and flowered by step 30 (a plant, not a stick).
    if strings[30].count("[") < 20:
        sys.exit("FAIL: the reference plant has only %d branches" % strings[30].count("["))


main()

#!/usr/bin/env python3
"""ABOP Fig. 1.24a-f, the six bracketed OL-system plants, and Fig. 1.9a-f, the Koch
curves, derived by an independent rewriter and compared segment by segment with what
fgsg draws for examples/abop/fig1_24*.fgsg and fig1_9*.fgsg, at the book's n and one
step less; and Fig. 5.5a, the cordate leaf, polygon by polygon
(examples/abop/fig5_5a.fgsg). The grammars are
written here again from the book, not read from the examples.
    plants.py FGSG REPO_ROOT
"""
import os
import sys
import tempfile

from lsystem_reference import check

# Fig. 1.24: n, delta, axiom, productions (ABOP p. 25).
PLANTS = {
    "a": (5, 25.7, "F", {"F": "F[+F]F[-F]F"}),
    "b": (5, 20.0, "F", {"F": "F[+F]F[-F][F]"}),
    "c": (4, 22.5, "F", {"F": "FF-[-F+F+F]+[+F-F-F]"}),
    "d": (7, 20.0, "X", {"X": "F[+X]F[-X]+X", "F": "FF"}),
    "e": (7, 25.7, "X", {"X": "F[+X][-X]FX", "F": "FF"}),
    "f": (5, 22.5, "X", {"X": "F-[[X]+X]+F[+FX]-X", "F": "FF"}),
}


# Fig. 1.9a-f, Koch curves: n and the production for F (ABOP p. 9); delta 90, axiom F-F-F-F.
KOCH = {
    "a": (4, "FF-F-F-F-F-F+F"),
    "b": (4, "FF-F-F-F-FF"),
    "c": (3, "FF-F+F-F-FF"),
    "d": (4, "FF-F--F-F"),
    "e": (5, "F-FF--F-F"),
    "f": (4, "F-F+F-F-F"),
}

# Fig. 5.5a, the cordate leaf: n, delta, axiom, productions (G written f).
LEAF = (20, 10.0, "[A][B]", {"A": "[+A{.].C.}", "B": "[-B{.].C.}", "C": "fC"})


def derive(axiom, rules, n):
    s = axiom
    for _ in range(n):
        s = "".join(rules.get(c, c) for c in s)
    return s


def main():
    fgsg, root = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as folder:
        for name, (n, angle, axiom, rules) in PLANTS.items():
            grammar = os.path.join(root, "examples/abop/fig1_24%s.fgsg" % name)
            for steps in (n - 1, n):
                check(fgsg, grammar, steps, derive(axiom, rules, steps), angle, folder)
        for name, (n, production) in KOCH.items():
            grammar = os.path.join(root, "examples/abop/fig1_9%s.fgsg" % name)
            for steps in (n - 1, n):
                check(fgsg, grammar, steps, derive("F-F-F-F", {"F": production}, steps), 90.0, folder)
        n, angle, axiom, rules = LEAF
        grammar = os.path.join(root, "examples/abop/fig5_5a.fgsg")
        for steps in (3, n):
            check(fgsg, grammar, steps, derive(axiom, rules, steps), angle, folder, polygons=True)


main()

#!/usr/bin/env python3
"""lpfg's `#consider` (cpfg's and L-Py's `consider:`) against an independent rewriter.

A signal b travels up an axis of a's through c's that context matching must not see:
with `#consider: a b d;` only a, b and d are seen (the c's, the turns and the segments
are stepped over), so `b < a` holds across `c`; the signal enters branches (a left
context leaves a '[' into the parent), waits at d until `b < d` turns it into b, and the
c's just before d grow an `f` each step (`c > d`, a right context stepping over c's).
This script rewrites the grammar in parallel by ABOP's context rules (lsystem_reference:
left_context / right_context with "skipped" = not listed), draws each string with ABOP's
turtle and checks that fgsg draws exactly those segments, for several step counts, in
the interpreter and the JIT, written as lpfg (`#consider: a b d;`), as cpfg and L-Py
(`consider: a b d`) and as its complement `#ignore: c;`. Without a declaration the c's
block every context (checked too: the reference then differs, so the test can fail).
    consider.py FGSG REPO_ROOT
"""
import os
import sys
import tempfile

from lsystem_reference import fgsg_obj, left_context, right_context, turtle, unmatched, write_grammar

AXIOM = "bcaca[+caca]cacdca[-aca]ca"
RULES = [  # (left, predecessor, right, successor): one rule per predecessor here
    ("b", "a", None, "b"),
    (None, "b", None, "Fc"),
    (None, "c", "d", "fc"),
    ("b", "d", None, "b"),
]
COMMANDS = set("Ff+-")  # fgsg steps over turtle commands without rules whatever is declared
ANGLE = 30.0


def step(s, skipped, rules=None):
    out = []
    for i, m in enumerate(s):
        for left, pred, right, succ in rules or RULES:
            if m == pred and (left is None or left_context(s, i, skipped) == left) and \
                    (right is None or right_context(s, i, skipped) == right):
                out.append(succ)
                break
        else:
            out.append(m)
    return "".join(out)


def derive(n, skipped, axiom=AXIOM, rules=None):
    s = axiom
    for _ in range(n):
        s = step(s, skipped, rules)
    return s


def grammar_text(declaration, axiom=AXIOM, rules=None):
    spaced = lambda s: " ".join(s)
    rules = "".join("%s%s%s -> %s;\n" % (left + " < " if left else "", pred, " > " + right if right else "",
                                         spaced(succ)) for left, pred, right, succ in rules or RULES)
    return ('attr n = 1;\nderive parallel n;\nturtle angle %g segments "lines";\n%s\naxiom: %s;\n%s'
            % (ANGLE, declaration, spaced(axiom), rules))


def documented_example(fgsg, folder):
    """docs/language.md's example: its string after 3 steps as the docs give it, drawn alike."""
    axiom, rules = "bcaca[+ca]ca", [("b", "a", None, "b"), (None, "b", None, "Fc")]
    got_string = derive(3, lambda m: m not in "ab", axiom, rules)
    if got_string != "FccFccFc[+cb]cb":
        sys.exit("FAIL: the documented example derives %s" % got_string)
    grammar = write_grammar(folder, "documented", grammar_text("#consider: a b;", axiom, rules))
    for engine in ("interp", "jit"):
        want = turtle(got_string, ANGLE)[0]
        got = fgsg_obj(fgsg, grammar, 3, folder, engine=engine)["l"]
        if len(want) != len(got) or unmatched(want, got, 1e-5):
            sys.exit("FAIL: the documented example (%s): fgsg %s, the reference %s" % (engine, got, want))
    print("ok: docs/language.md's #consider example, interp and jit")


def main():
    fgsg = sys.argv[1]
    considered = lambda m: m not in "abd"
    blocked = lambda m: m in COMMANDS
    cases = [("consider_lpfg", "#consider: a b d;", considered),
             ("consider_lpy", "consider: a b d", considered),
             ("ignore_c", "#ignore: c;", lambda m: m in COMMANDS or m == "c"),
             ("no_declaration", "", blocked)]
    steps = (1, 3, 6, 10)
    # The reference itself: the signal crosses the c's, enters both branches and passes d
    # only when the c's are not seen: by step 10 each of the axiom's b, 9 a's and d has
    # been the signal once and left one F; with the c's seen it never leaves its place.
    s10 = derive(10, considered)
    if s10.count("F") != 11 or "F" not in s10.split("[")[2] or derive(10, blocked).count("F") != 1:
        sys.exit("FAIL: the reference does not behave as described: %s / %s" % (s10, derive(10, blocked)))
    with tempfile.TemporaryDirectory() as folder:
        documented_example(fgsg, folder)
        for name, declaration, skipped in cases:
            grammar = write_grammar(folder, name, grammar_text(declaration))
            for engine in ("interp", "jit"):
                for n in steps:
                    want = turtle(derive(n, skipped), ANGLE)[0]
                    got = fgsg_obj(fgsg, grammar, n, folder, engine=engine)["l"]
                    missing = unmatched(want, got, 1e-5)
                    if len(want) != len(got) or missing:
                        sys.exit("FAIL: %s (%s) n=%d: fgsg has %d segments, the reference %d (%d missing)\n%s"
                                 % (name, engine, n, len(got), len(want), missing, derive(n, skipped)))
            print("ok: %s, %s steps, interp and jit" % (name, ", ".join(map(str, steps))))


if __name__ == "__main__":
    main()

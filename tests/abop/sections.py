#!/usr/bin/env python3
"""lpfg's decomposition and homomorphism sections (L-Py's decomposition and interpretation
rules) against an independent rewriter: after each step the decomposition rules are
applied pass after pass while one applies, at most `maximum depth` passes, and the
result is the string; before the turtle the homomorphism rules are applied the same way
to a copy, which only the turtle reads (L-Py's Lsystem.derive and its recursive
interpretation, written here from their description). fgsg's segments, vertex by vertex,
with the interpreter and with the JIT.
    sections.py FGSG REPO_ROOT
"""
import sys
import tempfile

from lpy_turtle import draw
from lsystem_reference import fgsg_obj, unmatched, write_grammar


def rewrite(s, rules):
    """One pass: each module some rule returns a successor for is replaced by it."""
    out, changed = [], False
    for symbol, args in s:
        successor = rules(symbol, args)
        if successor is None:
            out.append((symbol, args))
        else:
            out.extend(successor)
            changed = True
    return out, changed


def passes(s, rules, depth):
    for _ in range(depth):
        s, changed = rewrite(s, rules)
        if not changed:
            break
    return s


def derive(axiom, n, production, decomposition=None, decomposition_depth=1, homomorphism=None,
           homomorphism_depth=1):
    """The string the turtle reads after n steps."""
    s = axiom
    for _ in range(n):
        s, _ = rewrite(s, production)
        if decomposition:
            s = passes(s, decomposition, decomposition_depth)
    return passes(s, homomorphism, homomorphism_depth) if homomorphism else s


def check(fgsg, folder, name, text, n, modules, angle=90.0):
    grammar = write_grammar(folder, name, 'attr n = 1;\nderive parallel n;\nturtle angle %g segments "lines";\n' % angle
                            + text)
    want = draw(modules, angle=angle)[0]
    for engine in ("interp", "jit"):
        got = fgsg_obj(fgsg, grammar, n, folder, dims=3, engine=engine)["l"]
        missing = unmatched(want, got, 1e-5)
        if len(want) != len(got) or missing:
            raise SystemExit("FAIL: %s n=%d (%s): fgsg has %d segments, the reference %d (%d of the reference's "
                             "missing)\nfgsg: %s\nreference: %s" % (name, n, engine, len(got), len(want), missing,
                                                                    got, want))
    ends = [s[3:] for s in want]
    box = [(min(e[k] for e in ends), max(e[k] for e in ends)) for k in range(3)] if ends else []
    print("ok: %s n=%d, %d segments, end points within %s (interpreter and JIT)" % (name, n, len(want), box))


def main():
    fgsg = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        # The check: a homomorphism draws what the production's string stands for
        # (2 segments where lpfg draws 2; read as productions it drew 1).
        text = "axiom: A;\nproduction:\nA -> B;\nhomomorphism:\nB -> F F;\n"
        modules = derive([("A", [])], 1, lambda s, a: [("B", [])] if s == "A" else None,
                         homomorphism=lambda s, a: [("F", []), ("F", [])] if s == "B" else None)
        check(fgsg, folder, "homomorphism_two_segments", text, 1, modules)

        # Parameters, guards, depth 2, and the derived string untouched by the homomorphism:
        # A keeps growing because the productions never see C.
        def production(s, a):
            if s == "A":
                k = a[0]
                return [("F", [k]), ("[", []), ("+", []), ("B", [k]), ("]", []), ("A", [k + 1])]
            return None

        def homomorphism(s, a):
            if s == "A":
                return [("C", a), ("C", a)]
            if s == "B":
                return [("-", []), ("F", [a[0] * 0.5]), ("C", a)]
            if s == "C" and a[0] > 2:
                return [("F", [1.0])]
            return None

        for depth in (1, 2):
            text = ("axiom: A(1);\nA(k) -> F(k) [ + B(k) ] A(k + 1);\nhomomorphism:\nmaximum depth: %d;\n"
                    "A(k) -> C(k) C(k);\nB(k) -> - F(k * 0.5) C(k);\nC(k) : k > 2 -> F(1);\n" % depth)
            for n in (2, 4):
                modules = derive([("A", [1.0])], n, production, homomorphism=homomorphism, homomorphism_depth=depth)
                check(fgsg, folder, "homomorphism_depth%d" % depth, text, n, modules)

        # Decomposition: after each step, at most 3 passes; what it writes is the string, so
        # the next step's productions rewrite the J it made, and an I left over decomposes
        # further after the next step.
        def production2(s, a):
            if s == "A":
                return [("F", [1.0]), ("[", []), ("-", []), ("I", [a[0]]), ("]", []), ("A", [a[0] + 1])]
            if s == "J":
                return [("F", [0.25]), ("J", [])]
            return None

        def decomposition(s, a):
            if s == "I" and a[0] > 0:
                return [("F", [0.5]), ("+", []), ("J", []), ("I", [a[0] - 1])]
            return None

        text = ("axiom: A(4);\nA(k) -> F(1) [ - I(k) ] A(k + 1);\nJ -> F(0.25) J;\ndecomposition:\n"
                "maximum depth: 3\nI(k) : k > 0 -> F(0.5) + J I(k - 1);\n")
        for n in (1, 3, 5):
            modules = derive([("A", [4.0])], n, production2, decomposition=decomposition, decomposition_depth=3)
            check(fgsg, folder, "decomposition", text, n, modules)

        # L-Py's spelling: `interpretation:` is the homomorphism, `production:` goes back.
        text = "axiom: A;\ninterpretation:\nA -> F + F;\nproduction:\nA -> A B;\nB -> F;\n"
        modules = derive([("A", [])], 3, lambda s, a: [("A", []), ("B", [])] if s == "A" else
                         ([("F", [])] if s == "B" else None),
                         homomorphism=lambda s, a: [("F", []), ("+", []), ("F", [])] if s == "A" else None)
        check(fgsg, folder, "interpretation_then_production", text, 3, modules)


main()

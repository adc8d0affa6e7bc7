#!/usr/bin/env python3
"""Issue #44's footprint-shaping and scope operations written in fgsg's own dialect
(Setback, ShapeU, InnerRectangle, RotateScope ...): each NAME.fgsg of this folder runs with
both engines (--engine=interp and --engine=jit), which must write the same instances, and
the instances must match NAME.expect.json (the corpus's format and checks: count, extent,
bbox, area ...; ../corpus/run_corpus.py documents them). The .cga side of the same
operations is in ../corpus (files 50 and up).

    run_cases.py FGSG [NAME ...]      (no names: every NAME.fgsg of this folder)
"""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "corpus"))
from run_corpus import check, check_mesh  # noqa: E402  the corpus's expectation checks


def run_one(fgsg, name, work):
    with open(os.path.join(HERE, name + ".expect.json"), encoding="utf-8") as f:
        expect = json.load(f)
    texts, problems = {}, []
    for engine in ("interp", "jit"):
        inst = os.path.join(work, name + "." + engine + ".json")
        rep = os.path.join(work, name + "." + engine + ".report.json")
        mesh = os.path.join(work, name + "." + engine + (".obj" if "mesh" in expect else ".glb"))
        cmd = [fgsg, "run", os.path.join(HERE, name + ".fgsg"), "--engine=" + engine, "-o",
               mesh, "--instances", inst, "--report", rep] + expect.get("args", [])
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
        if run.returncode != 0:
            return ["%s: exit %d: %s" % (engine, run.returncode, run.stderr.strip()[:400])]
        with open(inst, encoding="utf-8") as f:
            texts[engine] = f.read()
        with open(rep, encoding="utf-8") as f:
            report = json.load(f)
        found = []
        check(expect, json.loads(texts[engine]), report, run.stderr, found)
        check_mesh(expect, mesh, found)
        problems += ["%s: %s" % (engine, p) for p in found]
    if texts["interp"] != texts["jit"]:
        problems.append("the engines' instances differ")
    return problems


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    fgsg = sys.argv[1]
    names = sys.argv[2:] or sorted(f[:-5] for f in os.listdir(HERE) if f.endswith(".fgsg"))
    failed = 0
    with tempfile.TemporaryDirectory() as work:
        for name in names:
            problems = run_one(fgsg, name, work)
            print(("FAIL " if problems else "PASS ") + name)
            for p in problems[:8]:
                print("     " + p)
            failed += bool(problems)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

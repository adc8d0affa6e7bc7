#!/usr/bin/env python3
"""envelope and contextCompare (issue #44) in the grammar compiled to a shared library: each
corpus file named here, compiled with `fgsg compile`, writes byte for byte the mesh that both
engines write (the corpus runs check the engines against each other and the values by hand).

    run_library.py FGSG RUN_LIBRARY CORPUS_DIR NAME ...
"""
import json
import os
import subprocess
import sys
import tempfile


def main():
    fgsg, run_library, corpus = (os.path.abspath(a) for a in sys.argv[1:4])
    failed = 0
    for name in sys.argv[4:]:
        rule = next(os.path.join(corpus, name + ext) for ext in (".cga", ".fgsg")
                    if os.path.exists(os.path.join(corpus, name + ext)))
        with open(os.path.join(corpus, name + ".expect.json")) as f:
            lots = ["--lots", os.path.join(corpus, json.load(f)["lots"])]
        with tempfile.TemporaryDirectory() as work:
            lib = os.path.join(work, "libenvelope.so")
            done = subprocess.run([fgsg, "compile", rule, "-o", lib, "-q"], capture_output=True, text=True, timeout=300)
            if done.returncode != 0:
                print("FAIL %s: fgsg compile: %s" % (name, done.stderr[:400]))
                failed += 1
                continue
            meshes = {}
            for way in ("library", "interp", "jit"):
                out = os.path.join(work, way + ".glb")
                cmd = [run_library, lib, "-o", out] if way == "library" else \
                    [fgsg, "run", rule, "--engine=" + way, "-o", out, "--instancing", "off", "--group-by", "none"]
                done = subprocess.run(cmd + ["--quiet"] + lots, capture_output=True, text=True, timeout=300)
                if done.returncode != 0:
                    print("FAIL %s: %s: %s" % (name, way, done.stderr[:400]))
                    break
                with open(out, "rb") as f:
                    meshes[way] = f.read()
            if len(meshes) == 3 and meshes["library"] == meshes["interp"] == meshes["jit"] and meshes["jit"]:
                print("PASS %s: library = interp = jit (%d bytes)" % (name, len(meshes["jit"])))
            else:
                print("FAIL %s: the meshes differ" % name)
                failed += 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

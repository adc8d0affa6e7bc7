#!/usr/bin/env python3
"""CityEngine's scatter in both dialects and both engines (issue #44).

Each rule file runs with --engine=interp and --engine=jit, which must write the same
instances byte for byte. Every point is the origin of the small cube its body inserts (the
translation of the instance's transform); the checks below test it against the domain
written out from the lot's dimensions (not from fgsg's geometry):

  surface_split.cga   3000 points on the 2 x 2 x 0.5 box's surface (each on a face within
                      1e-9); top and bottom hold 8 of its 12 m2, so 2/3 of the points, within
                      4.5 binomial standard deviations
  volume_l.cga        1000 points inside the extruded L (a point-in-L test), run by a rule;
                      scatter(surface, 0, ...) places nothing
  gaussian_scope.cga  400 gaussian points, all inside the scope box
  dialect.fgsg        fgsg's Scatter("volume"...) and Scatter("scope", ..., "gaussian", ...)
  --seed              the same seed gives the same points, another seed others
  library             with RUN_LIBRARY (tests/tools/run_library): the grammar compiled to a
                      shared library (fgsg compile) writes the same mesh as both engines
  errors              bad arguments are located errors (file:line:col) in both dialects

    run_scatter.py FGSG [RUN_LIBRARY]
"""
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOL = 1e-9


def run(fgsg, rule, work, engine, extra=()):
    inst = os.path.join(work, "inst.%s.json" % engine)
    cmd = [fgsg, "run", os.path.join(HERE, rule), "--engine=" + engine, "-o", os.path.join(work, "out.glb"),
           "--instances", inst] + list(extra)
    if rule.endswith(".cga"):
        lots = "lot2x2.geojson" if rule == "surface_split.cga" else \
            "../corpus/lots/l_shape.geojson" if rule == "volume_l.cga" else "../corpus/lots/rect10x6.geojson"
        cmd += ["--lots", os.path.join(HERE, lots)]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        raise AssertionError("%s %s: exit %d: %s" % (rule, engine, done.returncode, done.stderr.strip()[:600]))
    with open(inst, encoding="utf-8") as f:
        return f.read()


def points(text, symbol):
    return [i["transform"][12:15] for i in json.loads(text)["instances"] if i["symbol"] == symbol]


def both_engines(fgsg, rule, work, extra=()):
    a = run(fgsg, rule, work, "interp", extra)
    b = run(fgsg, rule, work, "jit", extra)
    assert a == b, "%s: the engines' instances differ" % rule
    return a


def inside_box(p, lo, hi):
    return all(lo[k] - TOL <= p[k] <= hi[k] + TOL for k in range(3))


def check_surface_split(fgsg, work):
    pts = points(both_engines(fgsg, "surface_split.cga", work), "Tree")
    assert len(pts) == 3000, "surface: %d points, expected 3000" % len(pts)
    lo, hi = (0, 0, -2), (2, 0.5, 0)
    caps = 0
    for p in pts:
        on_face = inside_box(p, lo, hi) and any(abs(p[k] - lo[k]) <= TOL or abs(p[k] - hi[k]) <= TOL for k in range(3))
        assert on_face, "surface: %s lies on no face of the box" % p
        caps += abs(p[1]) <= TOL or abs(p[1] - 0.5) <= TOL
    n, share = len(pts), 8 / 12
    bound = 4.5 * math.sqrt(n * share * (1 - share))
    assert abs(caps - n * share) <= bound, "surface: %d points on top and bottom, expected %.0f +- %.0f" % (
        caps, n * share, bound)
    return "surface: 3000 points on the faces, %d on top and bottom (2/3: %.0f +- %.0f)" % (caps, n * share, bound)


def in_l(p):
    x, y, z = p
    if not -TOL <= y <= 4 + TOL:
        return False
    wing = -TOL <= x <= 20 + TOL and -9 - TOL <= z <= TOL
    arm = -TOL <= x <= 9 + TOL and -18 - TOL <= z <= -9 + TOL
    return wing or arm


def check_volume_l(fgsg, work):
    text = both_engines(fgsg, "volume_l.cga", work)
    pts = points(text, "Tree")
    assert len(pts) == 1000, "volume: %d points, expected 1000" % len(pts)
    outside = [p for p in pts if not in_l(p)]
    assert not outside, "volume: %d points outside the L, e.g. %s" % (len(outside), outside[0])
    assert not points(text, "Never"), "volume: scatter(surface, 0, ...) placed something"
    arm = sum(1 for p in pts if p[2] < -9)
    share = 81 / 261
    bound = 4.5 * math.sqrt(1000 * share * (1 - share))
    assert abs(arm - 1000 * share) <= bound, "volume: %d points in the 9 x 9 arm, expected %.0f +- %.0f" % (
        arm, 1000 * share, bound)
    return "volume: 1000 points inside the L, %d in its 9 x 9 arm (%.0f +- %.0f)" % (arm, 1000 * share, bound)


def check_gaussian_scope(fgsg, work):
    pts = points(both_engines(fgsg, "gaussian_scope.cga", work), "Tree")
    assert len(pts) == 400, "gaussian: %d points, expected 400" % len(pts)
    bad = [p for p in pts if not inside_box(p, (0, 0, -6), (10, 4, 0))]
    assert not bad, "gaussian: %d points outside the scope, e.g. %s" % (len(bad), bad[0])
    mean_x = sum(p[0] for p in pts) / len(pts)
    # A normal of 1 m cut at its mean: on average sqrt(2 / pi) m from the left side.
    want, sd = math.sqrt(2 / math.pi), math.sqrt(1 - 2 / math.pi) / math.sqrt(len(pts))
    assert abs(mean_x - want) <= 4.5 * sd, "gaussian: mean x %.4f, expected %.4f +- %.4f" % (mean_x, want, 4.5 * sd)
    return "gaussian: 400 points in the scope, mean x %.3f (%.3f +- %.3f)" % (mean_x, want, 4.5 * sd)


def check_dialect(fgsg, work):
    text = both_engines(fgsg, "dialect.fgsg", work)
    inside, top = points(text, "Inside"), points(text, "Top")
    assert len(inside) == 500 and len(top) == 300, "fgsg: %d and %d points, expected 500 and 300" % (
        len(inside), len(top))
    for p in inside + top:
        assert inside_box(p, (1, 2, 3), (11, 6, 9)), "fgsg: %s outside the box" % p
    # About the top (y = 6) with a deviation of 0.2 m: on average sqrt(2 / pi) 0.2 m below it.
    below = sum(6 - p[1] for p in top) / len(top)
    want, sd = 0.2 * math.sqrt(2 / math.pi), 0.2 * math.sqrt(1 - 2 / math.pi) / math.sqrt(len(top))
    assert abs(below - want) <= 4.5 * sd, "fgsg: top points %.4f below the top, expected %.4f" % (below, want)
    return "fgsg dialect: 500 points in the volume, 300 gaussian about the top (%.3f m below it)" % below


def check_seeds(fgsg, work):
    a = run(fgsg, "surface_split.cga", work, "jit", ["--seed", "1"])
    b = run(fgsg, "surface_split.cga", work, "jit", ["--seed", "1"])
    c = run(fgsg, "surface_split.cga", work, "interp", ["--seed", "2"])
    assert a == b, "seeds: --seed 1 twice gave different points"
    pa, pc = points(a, "Tree"), points(c, "Tree")
    differ = sum(1 for p, q in zip(pa, pc) if p != q)
    assert differ == len(pa), "seeds: --seed 1 and 2 share %d points" % (len(pa) - differ)
    return "seeds: --seed 1 twice the same points, --seed 2 other points"


def check_library(fgsg, work, run_library):
    flat = ["--instancing", "off", "--group-by", "none"]  # the mesh as the library writes it
    for rule, lots in (("surface_split.cga", "lot2x2.geojson"), ("dialect.fgsg", None)):
        lib = os.path.join(work, "libscatter.so")
        extra = ["--lots", os.path.join(HERE, lots)] if lots else []
        done = subprocess.run([fgsg, "compile", os.path.join(HERE, rule), "-o", lib, "-q"], capture_output=True,
                              text=True, timeout=300)
        assert done.returncode == 0, "library: fgsg compile %s: %s" % (rule, done.stderr[:400])
        meshes = {}
        for way in ("library", "interp", "jit"):
            out = os.path.join(work, "%s.glb" % way)
            cmd = [run_library, lib, "-o", out] if way == "library" else \
                [fgsg, "run", os.path.join(HERE, rule), "--engine=" + way, "-o", out] + flat
            done = subprocess.run(cmd + ["--quiet", "--seed", "5"] + extra, capture_output=True, text=True, timeout=300)
            assert done.returncode == 0, "library: %s %s: %s" % (way, rule, done.stderr[:400])
            with open(out, "rb") as f:
                meshes[way] = f.read()
        assert meshes["library"] == meshes["interp"] == meshes["jit"], "library: %s: the meshes differ" % rule
    return "library: the compiled grammars write the engines' meshes byte for byte"


ERRORS = [
    # (file name, text, command, expected fragments of stderr)
    ("domain.cga", 'version "2023.0"\nLot --> scatter(surfaces, 10, uniform) { A. }\n', "check",
     ["domain.cga:2:17: error[E028]: scatter's domain is surface, volume, scope, not 'surfaces'"]),
    ("form.cga", 'version "2023.0"\nLot --> scatter(surface, 10, uniform, left, 2) { A. }\n', "check",
     ["form.cga:2:30: error[E028]: scatter's 5-argument form"]),
    ("block.cga", 'version "2023.0"\nLot --> extrude(3) { A. }\n', "check",
     ["block.cga:2:20: error[E018]: 'extrude' takes no { operations } body"]),
    ("negative.cga", 'version "2023.0"\nLot --> scatter(surface, -3, uniform) { A. }\n', "run",
     ["negative.cga:2:9: error[R002]: Scatter: the number of points must be 0 or more, not -3"]),
    ("huge.cga", 'version "2023.0"\nLot --> scatter(scope, 1e12, uniform) { A. }\n', "run",
     ["huge.cga:2:9: error[R002]: Scatter: 1e+12 points are more shapes than --max-shapes (20000000) allows"]),
    ("domain.fgsg", 'axiom: A;\nA ~> Scatter("volumes", 10, "uniform"){ B };\n', "check",
     ['domain.fgsg:2:14: error[E028]: \'Scatter\' takes surface, volume, scope here, not "volumes"']),
    ("label.fgsg", 'axiom: A;\nA ~> Scatter("scope", 10, "uniform"){ top: B };\n', "check",
     ["label.fgsg:2:39: error[E028]: unknown part 'top:' of Scatter"]),
    ("deviation.fgsg", 'axiom: A;\nA ~> Scatter("scope", 10, "gaussian", "center", 0){ B };\n', "run",
     ["deviation.fgsg:2:6: error[R002]: Scatter: the standard deviation must be a positive number, not 0"]),
]


def check_errors(fgsg, work):
    lots = os.path.join(HERE, "lot2x2.geojson")
    for name, text, mode, wants in ERRORS:
        path = os.path.join(work, name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        for engine in (["interp", "jit"] if mode == "run" else [None]):
            cmd = [fgsg, mode, name]
            if mode == "run":
                cmd += ["--engine=" + engine, "-o", os.path.join(work, "err.glb")]
                if name.endswith(".cga"):
                    cmd += ["--lots", lots]
            done = subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=work)
            assert done.returncode == 1, "%s: exit %d, expected 1: %s" % (name, done.returncode, done.stderr[:400])
            for want in wants:
                assert want in done.stderr, "%s (%s): stderr lacks %r:\n%s" % (name, engine, want, done.stderr[:800])
    return "errors: %d located errors as expected" % len(ERRORS)


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__)
        return 2
    fgsg = os.path.abspath(sys.argv[1])
    checks = [check_surface_split, check_volume_l, check_gaussian_scope, check_dialect, check_seeds, check_errors]
    if len(sys.argv) == 3:
        run_library = os.path.abspath(sys.argv[2])
        checks.append(lambda fgsg, work: check_library(fgsg, work, run_library))
    failed = 0
    with tempfile.TemporaryDirectory() as work:
        for check in checks:
            try:
                print("PASS " + check(fgsg, work))
            except AssertionError as e:
                failed += 1
                print("FAIL %s" % e)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

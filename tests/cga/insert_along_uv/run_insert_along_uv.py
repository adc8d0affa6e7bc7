#!/usr/bin/env python3
"""CityEngine's insertAlongUV in both dialects and both engines (issue #44).

Each rule file runs with --engine=interp and --engine=jit, which must write the same
instances and reports byte for byte. The expectations are worked out by hand from the
street's dimensions (the comments at the top of the rule files), not from fgsg's geometry:

  straight.cga        the built-in cube along the 10 x 2 lot, tileUV'd every 2.5 m: four
                      boxes; geometry.area() 58, nFaces 48, nVertices 20, the scope 10 x 0.5
                      x 2, the 20 corners (comp(v): x 0 2.5 5 7.5 10, y 0 0.5, z -2 0) to 1e-9,
                      and the written mesh's volume 10 m3 (faces looking out; float output)
  straight_fgsg.fgsg  fgsg's InsertAlongUV on a flat box S(10, 0, 2): the same, z 0 2
  normals.cga         the scope's y tilted 30 degrees: sheared boxes (area 4 (12 + 2.5 cos 30),
                      volume 10 cos 30); vertex.normal and keepPosition: the boxes of
                      straight.cga cut along the lot's diagonal (area 58, volume 10)
  library             with RUN_LIBRARY: the grammar compiled to a shared library (fgsg
                      compile) writes the same mesh as both engines
  errors              located errors (file:line:col) in both dialects and engines
  time limit          --max-seconds 0.3 stops an insertion of 3.9 million faces (24 s without
                      the limit) inside the operation: R004 at InsertAlongUV in both engines

    run_insert_along_uv.py FGSG [RUN_LIBRARY]
"""
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOL = 1e-9
LOTS = os.path.join(HERE, "lot10x2.geojson")


def run(fgsg, rule, work, engine):
    inst = os.path.join(work, "inst.%s.json" % engine)
    rep = os.path.join(work, "rep.%s.json" % engine)
    obj = os.path.join(work, "mesh.%s.obj" % engine)
    cmd = [fgsg, "run", os.path.join(HERE, rule), "--engine=" + engine, "-o", obj, "--group-by", "symbol",
           "--instances", inst, "--report", rep]
    if rule.endswith(".cga"):
        cmd += ["--lots", LOTS]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        raise AssertionError("%s %s: exit %d: %s" % (rule, engine, done.returncode, done.stderr.strip()[:600]))
    texts = []
    for path in (inst, rep):
        with open(path, encoding="utf-8") as f:
            texts.append(f.read())
    with open(obj, encoding="utf-8") as f:
        texts.append(f.read())
    return texts


def obj_group_volume(text, group):
    """The signed volume (divergence theorem) of the faces of OBJ group `group`."""
    verts, current, volume = [], None, 0.0
    for line in text.splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            verts.append(tuple(float(x) for x in parts[1:4]))
        elif parts[0] in ("g", "o"):
            current = parts[1] if len(parts) > 1 else None
        elif parts[0] == "f" and current == group:
            idx = [int(p.split("/")[0]) for p in parts[1:]]
            pts = [verts[i - 1 if i > 0 else len(verts) + i] for i in idx]
            for k in range(1, len(pts) - 1):
                a, b, c = pts[0], pts[k], pts[k + 1]
                volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                           a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
    return volume


def report_sum(reports, key):
    for scope in reports.values():
        if isinstance(scope, dict) and key in scope:
            return scope[key]["sum"]
    raise AssertionError("report %s missing: %s" % (key, json.dumps(reports)[:300]))


def check_straight(fgsg, work, rule, zs):
    a = run(fgsg, rule, work, "interp")
    b = run(fgsg, rule, work, "jit")
    assert a[0] == b[0] and a[1] == b[1], "%s: the engines' instances or reports differ" % rule
    reports = json.loads(a[1])
    sy, sz = (0.5, 2.0) if rule.endswith(".cga") else (0.5, 2.0)
    wants = {"rail.area": 58.0, "rail.faces": 48, "rail.vertices": 20, "rail.sx": 10.0, "rail.sy": sy, "rail.sz": sz}
    for key, want in wants.items():
        got = report_sum(reports, key)
        assert abs(got - want) <= TOL, "%s: %s is %r, expected %r" % (rule, key, got, want)
    corners = [i["transform"][12:15] for i in json.loads(a[0])["instances"] if i["symbol"] == "Corner"]
    expected = [(x, y, z) for x in (0, 2.5, 5, 7.5, 10) for y in (0, 0.5) for z in zs]
    assert len(corners) == 20, "%s: %d corners, expected 20" % (rule, len(corners))
    for c in corners:
        assert any(all(abs(c[k] - e[k]) <= TOL for k in range(3)) for e in expected), "%s: corner %s" % (rule, c)
    for e in expected:
        assert any(all(abs(c[k] - e[k]) <= TOL for k in range(3)) for c in corners), "%s: no corner at %s" % (rule, e)
    volume = obj_group_volume(a[2], "RailMesh")
    assert abs(volume - 10.0) <= 1e-4, "%s: the written mesh's volume is %r, expected 10 (faces looking out)" % (
        rule, volume)
    return "%s: 4 boxes, area 58, 48 faces, the 20 corners to 1e-9, volume %.6f, interp == jit" % (rule, volume)


def check_normals(fgsg, work):
    a = run(fgsg, "normals.cga", work, "interp")
    b = run(fgsg, "normals.cga", work, "jit")
    assert a[0] == b[0] and a[1] == b[1], "normals.cga: the engines' instances or reports differ"
    reports = json.loads(a[1])
    cos30 = math.cos(math.radians(30))
    wants = {"tilted.area": 4 * (12 + 2.5 * cos30), "rail.area": 58.0}
    for key, want in wants.items():
        got = report_sum(reports, key)
        assert abs(got - want) <= TOL, "normals.cga: %s is %r, expected %r" % (key, got, want)
    for group, want in (("TiltedMesh", 10 * cos30), ("RailMesh", 10.0)):
        volume = obj_group_volume(a[2], group)
        assert abs(volume - want) <= 1e-4, "normals.cga: %s's volume is %r, expected %r" % (group, volume, want)
    return "normals.cga: scope.y tilted 30 degrees: area 4 (12 + 2.5 cos 30), volume 10 cos 30; vertex.normal " \
           "and keepPosition: area 58, volume 10; interp == jit"


def check_library(fgsg, work, run_library):
    flat = ["--instancing", "off", "--group-by", "none"]  # the mesh as the library writes it
    for rule, lots in (("straight.cga", LOTS), ("straight_fgsg.fgsg", None)):
        lib = os.path.join(work, "libalonguv.so")
        extra = ["--lots", lots] if lots else []
        done = subprocess.run([fgsg, "compile", os.path.join(HERE, rule), "-o", lib, "-q"], capture_output=True,
                              text=True, timeout=300)
        assert done.returncode == 0, "library: fgsg compile %s: %s" % (rule, done.stderr[:400])
        meshes = {}
        for way in ("library", "interp", "jit"):
            out = os.path.join(work, "%s.glb" % way)
            cmd = [run_library, lib, "-o", out] if way == "library" else \
                [fgsg, "run", os.path.join(HERE, rule), "--engine=" + way, "-o", out] + flat
            done = subprocess.run(cmd + ["--quiet"] + extra, capture_output=True, text=True, timeout=300)
            assert done.returncode == 0, "library: %s %s: %s" % (way, rule, done.stderr[:400])
            with open(out, "rb") as f:
                meshes[way] = f.read()
        assert meshes["library"] == meshes["interp"] == meshes["jit"], "library: %s: the meshes differ" % rule
    return "library: the compiled grammars write the engines' meshes byte for byte"


def at(text, line, word):
    """file:line:col of the first `word` on line `line` (1-based) of `text`."""
    return "%d:%d" % (line, text.split("\n")[line - 1].index(word) + 1)


P = 'version "2023.0"\n'
ERRORS = [
    # (file name, text, command, the word the error points at (line 2), expected message)
    ("no_uvs.cga", P + 'Lot --> insertAlongUV(0, "builtin:cube", 0.5) X.\n', "run", "insertAlongUV",
     "error[R002]: InsertAlongUV: the shape has no uvs in set 0 (no setupProjection, texture or Texture above it"),
    ("other_set.cga", P + 'Lot --> setupProjection(0, scope.xz, 10, 2) insertAlongUV(3, "builtin:cube", 0.5) X.\n',
     "run", "insertAlongUV", "error[R002]: InsertAlongUV: the shape has no uvs in set 3"),
    ("deleted.cga", P + 'Lot --> setupProjection(0, scope.xz, 10, 2) deleteUV(0) insertAlongUV(0, "builtin:cube", 1) X.\n',
     "run", "insertAlongUV", "error[R002]: InsertAlongUV: the shape has no uvs in set 0 (deleteUV took them away)"),
    ("no_asset.cga", P + 'Lot --> setupProjection(0, scope.xz, 10, 2) insertAlongUV(0, "no_such_rail.obj", 0.5) X.\n',
     "run", "insertAlongUV", "error[R003]: "),
    ("overlap.cga", P + 'Lot --> extrude(3) setupProjection(0, scope.xz, 10, 2) insertAlongUV(0, "builtin:cube", 1) X.\n',
     "run", "insertAlongUV", "overlap, so the asset would be inserted on both there"),
    ("outside_v.cga",
     P + 'Lot --> setupProjection(0, scope.xz, 10, 2) translateUV(0, 0, 3) insertAlongUV(0, "builtin:cube", 1) X.\n',
     "run", "insertAlongUV", "error[R002]: insertAlongUV: the shape's v runs from 3 to 4, outside 0 to 1"),
    ("direction.cga", P + 'Lot --> insertAlongUV(0, "builtin:cube", 0.5, scope.z, alignPosition) X.\n', "check",
     "scope.z", "error[E028]: insertAlongUV's heightDirection is scope.y, vertex.normal, not 'scope.z'"),
    ("alignment.cga", P + 'Lot --> insertAlongUV(0, "builtin:cube", 0.5, vertex.normal, keep) X.\n', "check",
     "keep", "error[E028]: insertAlongUV's heightAlignment is alignPosition, keepPosition, not 'keep'"),
    ("set.cga", P + 'Lot --> insertAlongUV(12, "builtin:cube", 0.5) X.\n', "check", "12",
     "error[E028]: a uv set is a whole number from 0 to 9"),
    ("set.fgsg", 'axiom: A;\nA ~> S(10, 0, 2) InsertAlongUV(1.5, "cube", 0.5) B;\n', "check", "1.5",
     "error[E028]: a uv set is a whole number from 0 to 9"),
    ("asset.fgsg", 'axiom: A;\nA ~> S(10, 0, 2) InsertAlongUV(0, 3, 0.5) B;\n', "check", "3,",
     "error[E028]: InsertAlongUV's asset is a file name written as a string"),
    ("no_uvs.fgsg", 'axiom: A;\nA ~> S(10, 0, 2) InsertAlongUV(0, "cube", 0.5) B;\n', "run", "InsertAlongUV",
     "error[R002]: InsertAlongUV: the shape has no uvs in set 0"),
    ("no_asset.fgsg", 'axiom: A;\nA ~> S(10, 0, 2) SetupProjection("xz", 10, 2) InsertAlongUV(0, "gone.obj", 0.5) B;\n',
     "run", "InsertAlongUV", "error[R003]: "),
]


def check_errors(fgsg, work):
    for name, text, mode, word, want in ERRORS:
        path = os.path.join(work, name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        located = "%s:%s: " % (name, at(text, 2, word))
        for engine in (["interp", "jit"] if mode == "run" else [None]):
            cmd = [fgsg, mode, name]
            if mode == "run":
                cmd += ["--engine=" + engine, "-o", os.path.join(work, "err.glb")]
                if name.endswith(".cga"):
                    cmd += ["--lots", LOTS]
            done = subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=work)
            assert done.returncode == 1, "%s: exit %d, expected 1: %s" % (name, done.returncode, done.stderr[:400])
            assert located in done.stderr and want in done.stderr, "%s (%s): stderr lacks %r ... %r:\n%s" % (
                name, engine, located, want, done.stderr[:800])
    return "errors: %d located errors as expected" % len(ERRORS)


def check_time_limit(fgsg, work):
    # u runs 0..322 581 (10 m, tiles 0.000031 m): 3.9 million faces, within maxFaces.
    name = "slow.fgsg"
    text = ('axiom: A;\nA ~> S(10, 0, 2) SetupProjection("xz", 10, 2) TileUV(0.000031, 0) '
            'InsertAlongUV(0, "cube", 0.5) B;\n')
    with open(os.path.join(work, name), "w", encoding="utf-8") as f:
        f.write(text)
    want = "%s:%s: warning[R004]: derivation stopped after 0.3" % (name, at(text, 2, "InsertAlongUV"))
    for engine in ("interp", "jit"):
        done = subprocess.run([fgsg, "run", name, "--engine=" + engine, "--max-seconds", "0.3", "-o",
                               os.path.join(work, "slow.obj")], capture_output=True, text=True, timeout=300, cwd=work)
        assert done.returncode == 0 and want in done.stderr, "%s (%s): exit %d, stderr lacks %r:\n%s" % (
            name, engine, done.returncode, want, done.stderr[:800])
    return "time limit: R004 at InsertAlongUV in both engines"


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__)
        return 2
    fgsg = os.path.abspath(sys.argv[1])
    checks = [lambda f, w: check_straight(f, w, "straight.cga", (-2, 0)),
              lambda f, w: check_straight(f, w, "straight_fgsg.fgsg", (0, 2)), check_normals, check_errors,
              check_time_limit]
    if len(sys.argv) == 3:
        run_library = os.path.abspath(sys.argv[2])
        checks.append(lambda f, w: check_library(f, w, run_library))
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

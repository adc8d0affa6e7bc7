#!/usr/bin/env python3
"""scripts/mesh_digest.py (#51): the digest ignores vertex and triangle order and moves
below its precision, and sees what the golden files exist to catch: a moved vertex (at
the stated precision), a flipped triangle, one triangle more; its diff names the change.

Usage: test_mesh_digest.py SCRIPTS/mesh_digest.py
"""
import importlib.util
import os
import sys
import tempfile

spec = importlib.util.spec_from_file_location("mesh_digest", sys.argv[1])
md = importlib.util.module_from_spec(spec)
spec.loader.exec_module(md)
tmp = tempfile.mkdtemp(prefix="fgsg_mesh_digest_")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


def obj(name, vertices, faces):
    path = os.path.join(tmp, name)
    with open(path, "w") as f:
        f.writelines(f"v {x} {y} {z}\n" for x, y, z in vertices)
        f.writelines("f " + " ".join(str(i + 1) for i in face) + "\n" for face in faces)
    return path


# A unit square of two triangles, shared corners.
square = obj("a.obj", [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 1, 2), (0, 2, 3)])
base = md.digest(square)
# The same triangles: vertices in another order, triangles swapped and rotated.
same = obj("b.obj", [(1, 1, 0), (0, 1, 0), (0, 0, 0), (1, 0, 0)], [(0, 1, 2), (3, 0, 2)])
check(md.digest(same) == base, "reordered vertices and triangles change the digest")
check(md.diff(base, md.digest(same)) == "", "diff reports equal digests as different")
# Below the precision (1e-4): no change; above it: the triangle is named.
check(md.digest(obj("c.obj", [(0, 0, 0), (1.00001, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 1, 2), (0, 2, 3)])) == base,
      "a move below the precision changes the digest")
moved = md.digest(obj("d.obj", [(0, 0, 0), (1.001, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 1, 2), (0, 2, 3)]))
report = md.diff(base, moved)
check("+ t 0.0000 0.0000 0.0000 | 1.0010 0.0000 0.0000 | 1.0000 1.0000 0.0000" in report, f"moved vertex: {report}")
check("bbox.max: expected 1.0000 1.0000 0.0000, got 1.0010 1.0000 0.0000" in report, f"moved vertex: {report}")
# A flipped triangle faces the other way: not the same geometry.
flipped = md.digest(obj("e.obj", [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 2, 1), (0, 2, 3)]))
check(flipped != base and "- t 0.0000 0.0000 0.0000 | 1.0000 0.0000 0.0000 | 1.0000 1.0000 0.0000" in md.diff(base, flipped),
      "a flipped triangle is not seen")
# Large meshes are summarised and hashed; one triangle more shows in the counts and hash.
hashed = md.digest(square, full_limit=1)
more = md.digest(obj("f.obj", [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 1, 2), (0, 2, 3), (0, 1, 3)]),
                 full_limit=1)
check("geometry.sha256 " in hashed and "\nt " not in hashed, "a digest over the limit still lists triangles")
report = md.diff(hashed, more)
check("triangles: expected 2, got 3" in report and "geometry.sha256" in report, f"one more triangle: {report}")
check("area: expected 1, got 1.5" in report, f"one more triangle: {report}")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("mesh_digest: all checks passed")

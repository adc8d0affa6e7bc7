#!/usr/bin/env python3
"""A textured asset cut by trim planes keeps its texture (issue #44).

run_trim_textured.py FGSG ROOT: runs trim_textured.cga (on tests/cga/corpus/lots/square10)
and trim_textured.fgsg with --engine=interp and --engine=jit, each as an OBJ (+ .mtl) and a
.glb grouped by symbol, and trim_textured_rule.cga (each i() going on to a rule that ends in
trim_textured.cga's leaf) the same way, and requires
* trim_textured_rule.cga's OBJ, .mtl and .glb to be trim_textured.cga's bytes;
* the two engines' files to be the same bytes, the Khronos validator to pass the .glb with
  no errors and no warnings;
* in the OBJ, every corner of the cut pieces (Corner, Up) to carry the texture coordinate
  tex_cube.obj's one affine map gives the cube's point there (u = 0.25 + 0.5 x + 0.125 z,
  v = 0.1 + 0.8 y; the point read back through the instance's transform, zUp turned back),
  the hand-computed cut corners with their u v and normals, the cut piece's area and
  volume (92 + 20 sqrt 2 m2, 60 m3), its faces drawing grid.png, and Inside textured too;
  every face corner's vt and vn one the file has (Plain, an untextured cube, is written
  first: the lists count on their own);
* in the .glb, the cut pieces' primitives to have TEXCOORD_0 with the OBJ's coordinates
  (v flipped, as glTF counts it) and a material whose base colour texture is grid.png's PNG.
Exits 1 on any failure."""
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile

TOL = 1e-5
failures = []


def fail(text):
    failures.append(text)
    print("FAIL " + text)


def cube_uv(p):
    x, y, z = p
    return (0.25 + 0.5 * x + 0.125 * z, 0.1 + 0.8 * y)


def read_obj(path):
    """{group: [(material, [(position, uv or None, normal or None), ...]), ...]}, and the .mtl's
    {material: map_Kd}."""
    v, vt, vn, groups, group, material = [], [], [], {}, "", None
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                v.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == "vt":
                vt.append(tuple(float(x) for x in w[1:3]))
            elif w[0] == "vn":
                vn.append(tuple(float(x) for x in w[1:4]))
            elif w[0] in ("g", "o"):
                group = w[1] if len(w) > 1 else ""
            elif w[0] == "usemtl":
                material = w[1]
            elif w[0] == "f":
                corners = []
                for t in w[1:]:
                    ix = t.split("/")
                    uv = int(ix[1]) if len(ix) > 1 and ix[1] else None
                    n = int(ix[2]) if len(ix) > 2 and ix[2] else None
                    if (uv or 0) > len(vt) or (n or 0) > len(vn):
                        fail(f"{path}: face corner {t} names a vt or vn the file does not have")
                        uv = n = None
                    corners.append((v[int(ix[0]) - 1], vt[uv - 1] if uv else None, vn[n - 1] if n else None))
                groups.setdefault(group.rstrip("."), []).append((material, corners))
    maps, name = {}, None
    with open(path[:-4] + ".mtl") as f:
        for line in f:
            w = line.split()
            if w and w[0] == "newmtl":
                name = w[1]
            elif w and w[0] == "map_Kd":
                maps[name] = os.path.basename(w[-1])
    return groups, maps


def inverse_affine(t):
    """The inverse of a column-major 4x4 affine transform, as a function of a point."""
    m = [[t[0], t[4], t[8]], [t[1], t[5], t[9]], [t[2], t[6], t[10]]]
    d = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    inv = [[(m[(j + 1) % 3][(i + 1) % 3] * m[(j + 2) % 3][(i + 2) % 3] -
             m[(j + 1) % 3][(i + 2) % 3] * m[(j + 2) % 3][(i + 1) % 3]) / d for j in range(3)] for i in range(3)]
    return lambda p: tuple(sum(inv[i][j] * (p[j] - t[12 + j]) for j in range(3)) for i in range(3))


def near(a, b, tol=TOL):
    return a is not None and b is not None and len(a) == len(b) and all(abs(x - y) <= tol for x, y in zip(a, b))


def area_volume(faces):
    area = volume = 0.0
    for _, corners in faces:
        pts = [c[0] for c in corners]
        for k in range(1, len(pts) - 1):
            a, b, c = pts[0], pts[k], pts[k + 1]
            u = [b[i] - a[i] for i in range(3)]
            w = [c[i] - a[i] for i in range(3)]
            cross = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
            area += 0.5 * math.sqrt(sum(x * x for x in cross))
            volume += sum(a[i] * (b[(i + 1) % 3] * c[(i + 2) % 3] - b[(i + 2) % 3] * c[(i + 1) % 3])
                          for i in range(3)) / 6
    return area, volume


# Per cut symbol: its point (x, y, z) of the cube from its box's (unit) point, and the
# hand-computed cut corners: the box's point -> u v (the box x 8..12, y 0..10, z 0..2 of
# the wall: (0.5, 0, 0) is world (10, 0, 0) in the .cga, (1, 0, 1) world (12, 0, 2)).
CUT = {
    "Corner": (lambda u: u, {(0.5, 0, 0): (0.5, 0.1), (0.5, 1, 0): (0.5, 0.9), (1, 0, 1): (0.875, 0.1)}),
    "Up": (lambda u: (u[0], 1 - u[2], u[1]), {(0.5, 0, 0): (0.5, 0.9), (0.5, 1, 0): (0.625, 0.9)}),
}
S = 1 / math.sqrt(2)
# The normals of Corner's faces in the wall's axes (its right face cut away, the cap's
# added): the .cga's world axes.
CORNER_NORMALS = [(0, 0, 1), (0, 0, -1), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (S, 0, -S)]


def check_obj(label, obj, instances):
    groups, maps = read_obj(obj)
    transforms = {i["symbol"].rstrip("."): i for i in instances["instances"]}
    for symbol in ("Corner", "Up", "Inside"):
        if symbol not in groups:
            if symbol != "Up" or label.startswith("trim_textured.fgsg"):
                fail(f"{label}: no group {symbol} in the OBJ (groups: {sorted(groups)})")
            continue
        faces = groups[symbol]
        untextured = [m for m, _ in faces if maps.get(m) != "grid.png"]
        if untextured:
            fail(f"{label}: {symbol}: {len(untextured)} faces do not draw grid.png (materials {set(untextured)})")
        if symbol == "Inside":
            if transforms[symbol]["asset"] == "(own geometry)":
                fail(f"{label}: Inside was cut")
            continue
        inst = transforms[symbol]
        if inst["asset"] != "(own geometry)":
            fail(f"{label}: {symbol} is {inst['asset']}, not a cut piece")
            continue
        to_unit = inverse_affine(inst["transform"])
        to_cube, want = CUT[symbol]
        found = {}
        for _, corners in faces:
            for p, uv, n in corners:
                expect = cube_uv(to_cube(to_unit(p)))
                if not near(uv, expect):
                    fail(f"{label}: {symbol}: corner {p} has u v {uv}, expected {expect}")
                    return
                for w, wuv in want.items():
                    if near(to_unit(p), w, 1e-6) and near(uv, wuv):
                        found[w] = found.get(w, 0) + 1
        for w in want:
            if w not in found:
                fail(f"{label}: {symbol}: no corner at {w} with u v {want[w]}")
        area, volume = area_volume(faces)
        if abs(area - (92 + 20 * math.sqrt(2))) > 1e-3 or abs(volume - 60) > 1e-3:
            fail(f"{label}: {symbol}: area {area}, volume {volume}; expected 120.2842712, 60")
        if symbol == "Corner":
            t = inst["transform"]
            axes = [[t[4 * c + r] / math.sqrt(sum(t[4 * c + k] ** 2 for k in range(3))) for r in range(3)] for c in range(3)]
            normals = {tuple(round(x, 5) + 0.0 for x in n) for _, corners in faces for _, _, n in corners if n}
            want_normals = {tuple(round(sum(axes[c][r] * n[c] for c in range(3)), 5) + 0.0 for r in range(3))
                            for n in CORNER_NORMALS}
            if normals != want_normals:
                fail(f"{label}: Corner's normals {sorted(normals)}, expected {sorted(want_normals)}")
    return groups


def read_glb(path):
    data = open(path, "rb").read()
    length = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + length])
    rest = 20 + length
    blob = data[rest + 8:rest + 8 + struct.unpack_from("<I", data, rest)[0]]
    return doc, blob


def accessor(doc, blob, k):
    a = doc["accessors"][k]
    view = doc["bufferViews"][a["bufferView"]]
    n = {"VEC2": 2, "VEC3": 3}[a["type"]]
    stride = view.get("byteStride", 4 * n)
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    return [struct.unpack_from("<%df" % n, blob, start + i * stride) for i in range(a["count"])]


def check_glb(label, glb, groups, root):
    doc, blob = read_glb(glb)
    png = open(os.path.join(root, "tests", "cga", "trim_textured", "assets", "grid.png"), "rb").read()

    def leaves():
        out = {}

        def visit(k, name):
            node = doc["nodes"][k]
            name = node.get("name", name)
            if "mesh" in node:
                out.setdefault(name.rstrip("."), []).extend(doc["meshes"][node["mesh"]]["primitives"])
            for c in node.get("children", []):
                visit(c, name)

        for r in doc["scenes"][0]["nodes"]:
            visit(r, "")
        return out

    prims = leaves()
    for symbol in ("Corner", "Up"):
        if symbol not in groups:
            continue
        if symbol not in prims:
            fail(f"{label}: no node {symbol} in the .glb")
            continue
        have = set()
        for prim in prims[symbol]:
            mat = doc["materials"][prim["material"]] if "material" in prim else {}
            tex = mat.get("pbrMetallicRoughness", {}).get("baseColorTexture")
            if tex is None or "TEXCOORD_0" not in prim["attributes"]:
                fail(f"{label}: {symbol}: a primitive without its texture or TEXCOORD_0")
                continue
            image = doc["images"][doc["textures"][tex["index"]]["source"]]
            view = doc["bufferViews"][image["bufferView"]]
            if blob[view.get("byteOffset", 0):view.get("byteOffset", 0) + view["byteLength"]] != png:
                fail(f"{label}: {symbol}: its base colour image is not grid.png")
            have |= {(round(u, 5), round(1 - v, 5)) for u, v in accessor(doc, blob, prim["attributes"]["TEXCOORD_0"])}
        want = {(round(uv[0], 5), round(uv[1], 5)) for _, corners in groups[symbol] for _, uv, _ in corners}
        if have != want:
            fail(f"{label}: {symbol}: the .glb's texture coordinates {sorted(have)} are not the OBJ's {sorted(want)}")


def main():
    fgsg, root = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    here = os.path.join(root, "tests", "cga", "trim_textured")
    validator = os.path.join(root, "scripts", "validate-gltf.js")
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copytree(os.path.join(here, "assets"), os.path.join(tmp, "assets"))
        meshes = {}  # per grammar: the interpreter's OBJ, .mtl and .glb bytes
        for name in ("trim_textured.cga", "trim_textured.fgsg", "trim_textured_rule.cga"):
            grammar = os.path.join(tmp, name)
            shutil.copy(os.path.join(here, name), grammar)
            lots = ["--lots", os.path.join(root, "tests", "cga", "corpus", "lots", "square10.geojson")] \
                if name.endswith(".cga") else []
            outputs = {}
            for engine in ("interp", "jit"):
                label = f"{name} ({engine})"
                # The same file names: the same bytes (the rule variant's those of trim_textured.cga).
                rule = name == "trim_textured_rule.cga"
                os.makedirs(os.path.join(tmp, engine + "-rule" if rule else engine), exist_ok=True)
                base = os.path.join(tmp, engine + "-rule" if rule else engine,
                                    "trim_textured_cga" if rule else name.replace(".", "_"))
                ok = True
                for target in (base + ".obj", base + ".glb"):
                    run = subprocess.run([fgsg, "run", grammar, f"--engine={engine}", "-o", target, "--group-by", "symbol",
                                          "--instances", base + ".json", "-q"] + lots,
                                         capture_output=True, text=True, timeout=120)
                    if run.returncode != 0:
                        fail(f"{label}: fgsg run exited {run.returncode}: {run.stderr.strip()}")
                        ok = False
                        break
                if not ok:
                    continue
                outputs[engine] = b"".join(open(base + ext, "rb").read() for ext in (".obj", ".mtl", ".glb", ".json"))
                if engine == "interp":
                    meshes[name] = b"".join(open(base + ext, "rb").read() for ext in (".obj", ".mtl", ".glb"))
                v = subprocess.run(["node", validator, "--strict", base + ".glb"], capture_output=True, text=True)
                if v.returncode != 0 or ": 0 errors, 0 warnings" not in v.stdout + v.stderr:
                    fail(f"{label}: gltf-validator: {(v.stdout + v.stderr).strip()[-2000:]}")
                groups = check_obj(label, base + ".obj", json.load(open(base + ".json")))
                if groups:
                    check_glb(label, base + ".glb", groups, root)
            if len(outputs) == 2 and outputs["interp"] != outputs["jit"]:
                fail(f"{name}: the engines' outputs differ")
        if meshes.get("trim_textured_rule.cga") != meshes.get("trim_textured.cga"):
            fail("trim_textured_rule.cga: its OBJ, .mtl or .glb differ from trim_textured.cga's "
                 "(an i() going on to a rule outputs the asset once, at the leaf)")
    print("%s: %d failure(s)" % ("PASS" if not failures else "FAIL", len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

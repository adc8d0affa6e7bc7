#!/usr/bin/env python3
"""CGA's materials and uv operations (issue #44) read back from the glTF scenes fgsg writes.

run_materials.py FGSG ROOT: runs materials.cga / materials.fgsg on lots/rect20x10,
uv_operations.cga / uv_operations.fgsg, uv_delete.cga / uv_delete.fgsg and uv_sets.cga /
uv_sets.fgsg, uv_layers.cga / uv_layers.fgsg on lots/street40x12 and uv_world.cga /
uv_world.fgsg on lots/square10 (tests/cga/corpus/lots), each
with --engine=interp and --engine=jit, as a .gltf scene (--instancing off --group-by
symbol: every leaf baked into its symbol's node) and as a grouped OBJ; requires the two
engines' files to be the same bytes, the Khronos validator to find no errors and no
warnings, and the material factors, texture slots and texture coordinate ranges the
.cga files' comments compute by hand; then the located errors of ERRORS. Exits 1 on any
failure."""
import base64
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile

from gltf_scene import leaves

TOL = 1e-5

# Per leaf symbol: (roughness, metallic, baseColorFactor or None (the symbol's own colour,
# not checked), alphaMode or None, base colour image, normal map).
MATERIALS = {
    "M1": (0.3, 1.0, None, None, False, False),
    "M2": (0.8, 0.0, "alpha 0.5", "BLEND", False, False),
    "M3": (0.8, 0.0, [1.0, 0.4, 0.6, 1.0], None, False, False),
    "M4": (0.8, 0.0, [1.0, 0.5, 1.0, 1.0], None, False, False),
    "M5": (0.55, 0.0, None, None, True, True),
}
# Per leaf symbol: u min, u max, v min, v max.
UV_RANGES = {
    "U1": (0, 2, 0, 12),
    "U2": (0, 1, 0, 2),
    "U3": (0, 4, 0, 18),
    "U4": (0.5, 2.5, -1, 5),
    "U5": (-6, 0, 0, 2),
    "U6": (0, 4, 0, 2),
    "U7": (0, 1, 0, 1),
    "U8": (0, 1, 0, 12),
    "U9": (0, 1 / 3, 0, 1),
    "U10": (0, 1, 0, 6),
    "W1": (0, 1, -5, 0),
    "W2": (2, 4, -4, 0),
    "D2": (0, 2, 0, 6),
    "D3": (0, 2, 0, 6),
    "D4": (0, 4, 0, 18),
    "D6": (0, 2, 0, 6),
    "S1": (0, 2, 0, 12),
    "S2": (0, 2, 0, 6),
    "S3": (0, 4, 0, 18),
    "S4": (0.5, 2.5, -1, 5),
    "S5": (0, 2, 0, 6),
    "S6": (0, 4, 0, 12),
    "S8": (0, 4, 0, 4),
    "S9": (0, 1, 0, 6),
    "S10": (0, 2, 0, 6),
}
# Leaves whose coordinates deleteUV removed: no TEXCOORD_0, no image, no `vt` in the OBJ.
NO_UV = ("D1", "D5")
# uv_sets' leaf whose set 0 an empty set was copied over: no TEXCOORD_0, no image.
NO_UV_SETS = ("S7",)
# uv_layers (uv sets 1..9 written as TEXCOORD_n): per leaf, per TEXCOORD_n its (u min, u max,
# v min, v max) or ZEROS (a set the leaf lacks below its highest one), and the normal map's
# texCoord (None: no normal map; 0: glTF's default, no texCoord written).
ZEROS = "zeros"
UV_LAYERS = {
    "L1": ({0: (0, 4, 0, 6), 1: (0, 8, 0, 3)}, None),
    "L2": ({0: ZEROS, 1: ZEROS, 2: ZEROS, 3: (0, 8, 0, 4)}, None),
    "L3": ({0: (0, 2, 0, 3), 1: ZEROS, 2: ZEROS, 3: ZEROS, 4: ZEROS, 5: (0, 8, 0, 12)}, 5),
    "L4": ({0: (0, 2, 0, 3)}, 0),
    "L5": ({}, None),
}
# uv_layers' geometry.du/dv(k, uvSpace) reports, by hand (uv_layers.cga's comment).
UV_LAYER_REPORTS = {"L1.du1": 8, "L1.dv1": 3, "L2.du3": 8, "L2.dv3": 4, "L2.du0": 0, "L5.du2": 0}
# The .mtl of the grouped OBJ: per material of these leaves, d, Pr, Pm and whether `norm`.
MTL = {"M1": ("1", "0.3", "1"), "M2": ("0.5", "0.8", "0"), "M5": ("1", "0.55", "0")}

# Located errors, both engines: (file name, source, the diagnostic's start).
ERRORS = [
    ("e1.cga", 'version "2023.0"\n@StartRule\nLot --> report("d", geometry.du(10, uvSpace)) X.\n',
     "e1.cga:3:33: error[E028]: a uv set is a whole number from 0 to 9"),
    ("e15.cga", 'version "2023.0"\n@StartRule\nLot --> report("d", geometry.dv(1, unitSpace)) X.\n',
     "e15.cga:3:36: error[E801]"),
    ("e2.cga", 'version "2023.0"\n@StartRule\nLot --> normalizeUV(0, uv, separatePerFace) X.\n',
     "e2.cga:3:28: error[E801]"),
    ("e3.cga", 'version "2023.0"\n@StartRule\nLot --> setupProjection(0, scope.xw, 1, 1) X.\n',
     "e3.cga:3:28: error[E028]"),
    ("e4.fgsg", 'axiom: Lot;\nLot ~> Material("shininess", 1) X;\n', "e4.fgsg:2:17: error[E028]"),
    ("e5.fgsg", 'axiom: Lot;\nLot ~> SetupProjection("xy", 0, 1) X;\n', "e5.fgsg:2:8: error[R027]"),
    ("e6.cga", 'version "2023.0"\n@StartRule\nLot --> deleteUV(10) X.\n',
     "e6.cga:3:18: error[E028]: a uv set is a whole number from 0 to 9"),
    ("e7.cga", 'version "2023.0"\n@StartRule\nLot --> copyUV(0, -1) X.\n',
     "e7.cga:3:19: error[E028]: a uv set is a whole number from 0 to 9"),
    ("e8.cga", 'version "2023.0"\n@StartRule\nLot --> copyUV(0) X.\n', "e8.cga:3:9: error[E016]"),
    ("e9.cga", 'version "2023.0"\n@StartRule\nLot --> deleteUV() X.\n', "e9.cga:3:9: error[E016]"),
    ("e10.fgsg", 'axiom: Lot;\nLot ~> DeleteUV(0, 1) X;\n', "e10.fgsg:2:8: error[E016]"),
    ("e11.fgsg", 'axiom: Lot;\nLot ~> ScaleUV(1, 1, 12) X;\n',
     "e11.fgsg:2:22: error[E028]: a uv set is a whole number from 0 to 9 (CityEngine's texture layers), written as one, "
     "not 12"),
    ("e12.cga", 'version "2023.0"\n@StartRule\nLot --> setupProjection(1.5, scope.xz, 1, 1) X.\n',
     "e12.cga:3:25: error[E028]: a uv set is a whole number from 0 to 9"),
    ("e13.fgsg", 'axiom: Lot;\nLot ~> CopyUV(0, 10) X;\n', "e13.fgsg:2:18: error[E028]"),
    ("e14.fgsg", 'axiom: Lot;\nLot ~> RotateUV(90, Rand(0, 1)) X;\n', "e14.fgsg:2:21: error[E028]"),
]

failures = []


def fail(what):
    failures.append(what)
    print("FAIL", what)


def accessor_floats(doc, buffer, index):
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    width = {"VEC2": 2, "VEC3": 3}[a["type"]]
    stride = view.get("byteStride", 4 * width)
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    return [struct.unpack_from("<%df" % width, buffer, start + i * stride) for i in range(a["count"])]


def indices(doc, buffer, index):
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    fmt = {5121: "B", 5123: "H", 5125: "I"}[a["componentType"]]
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    return struct.unpack_from("<%d%s" % (a["count"], fmt), buffer, start)


def near(a, b):
    return abs(a - b) <= TOL * max(1.0, abs(b))


def check_materials(doc, label):
    by_leaf = leaves(doc)
    for leaf, (rough, metal, color, alpha_mode, image, normal) in MATERIALS.items():
        prims = by_leaf.get(leaf)
        if not prims:
            fail(f"{label}: no node {leaf}")
            continue
        mats = {p["material"] for p in prims if "material" in p}
        if len(mats) != 1:
            fail(f"{label}: {leaf} has materials {sorted(mats)}, one expected")
            continue
        m = doc["materials"][mats.pop()]
        pbr = m["pbrMetallicRoughness"]
        if not near(pbr["roughnessFactor"], rough) or not near(pbr["metallicFactor"], metal):
            fail(f"{label}: {leaf} roughness/metallic {pbr['roughnessFactor']}/{pbr['metallicFactor']}, "
                 f"expected {rough}/{metal}")
        factor = pbr.get("baseColorFactor", [1, 1, 1, 1])
        if color == "alpha 0.5":
            if not near(factor[3], 0.5):
                fail(f"{label}: {leaf} alpha {factor[3]}, expected 0.5")
        elif color is not None and not all(near(x, y) for x, y in zip(factor, color)):
            fail(f"{label}: {leaf} baseColorFactor {factor}, expected {color}")
        elif color is None and factor[3] != 1:
            fail(f"{label}: {leaf} alpha {factor[3]}, expected 1")
        if m.get("alphaMode") != alpha_mode:
            fail(f"{label}: {leaf} alphaMode {m.get('alphaMode')}, expected {alpha_mode}")
        if ("baseColorTexture" in pbr) != image or ("normalTexture" in m) != normal:
            fail(f"{label}: {leaf} textures {sorted(k for k in pbr if k.endswith('Texture'))} "
                 f"normal {'normalTexture' in m}, expected image {image} normal {normal}")
        if image and normal and pbr["baseColorTexture"]["index"] == m["normalTexture"]["index"]:
            fail(f"{label}: {leaf} draws one image as its colour and its normals")


def check_uvs(doc, buffer, label, prefix):
    by_leaf = leaves(doc)
    for leaf, expected in UV_RANGES.items():
        if not leaf.startswith(prefix):
            continue
        uvs = []
        for p in by_leaf.get(leaf, []):
            if "TEXCOORD_0" not in p["attributes"]:
                continue
            coords = accessor_floats(doc, buffer, p["attributes"]["TEXCOORD_0"])
            # glTF's v runs down the image: fgsg's v (up) is 1 - it.
            uvs += [(coords[i][0], 1 - coords[i][1]) for i in indices(doc, buffer, p["indices"])]
        if not uvs:
            fail(f"{label}: {leaf} has no texture coordinates")
            continue
        got = (min(u for u, v in uvs), max(u for u, v in uvs), min(v for u, v in uvs), max(v for u, v in uvs))
        if not all(near(g, e) for g, e in zip(got, expected)):
            fail(f"{label}: {leaf} uv range {tuple(round(g, 6) for g in got)}, expected {expected}")


def check_no_uvs(doc, obj_path, label):
    """The NO_UV leaves have no texture coordinates nor image in the glTF, no `vt` in the
    OBJ; the others of uv_delete do."""
    check_untextured_leaves(doc, NO_UV, label, "deleteUV")
    vt = {}
    group = None
    for line in open(obj_path):
        if line.startswith("g "):
            group = line[2:].strip().rstrip(".")
            vt.setdefault(group, 0)
        elif line.startswith("vt ") and group is not None:
            vt[group] += 1
    for leaf in ("D1", "D2", "D3", "D4", "D5", "D6"):
        if leaf not in vt:
            fail(f"{label}: no group {leaf} in the OBJ")
        elif (vt[leaf] == 0) != (leaf in NO_UV):
            fail(f"{label}: the OBJ's group {leaf} has {vt[leaf]} vt lines")


def check_untextured_leaves(doc, names, label, after):
    """Each leaf named exists in the glTF and has neither texture coordinates nor an image."""
    by_leaf = leaves(doc)
    for leaf in names:
        prims = by_leaf.get(leaf)
        if not prims:
            fail(f"{label}: no node {leaf}")
        for p in prims or []:
            textured = "baseColorTexture" in doc["materials"][p["material"]]["pbrMetallicRoughness"]
            if "TEXCOORD_0" in p["attributes"] or textured:
                fail(f"{label}: {leaf} has texture coordinates or an image after {after}")


def check_no_uvs_sets(doc, label):
    check_untextured_leaves(doc, NO_UV_SETS, label, "an empty set was copied over set 0")


def check_uv_layers(doc, buffer, label):
    """Each uv_layers leaf's TEXCOORD_n: exactly the expected ones, each set's range (fgsg's v
    up is 1 - glTF's), the zero-filled ones all 0 as written; L1's set 1 per vertex from its
    set 0 (u1 = 2 u0, v1 = v0 / 2); the normal map's texCoord; the du/dv reports."""
    by_leaf = leaves(doc)
    for leaf, (sets, normal) in UV_LAYERS.items():
        prims = by_leaf.get(leaf)
        if not prims:
            fail(f"{label}: no node {leaf}")
            continue
        for p in prims:
            names = sorted(k for k in p["attributes"] if k.startswith("TEXCOORD_"))
            want = sorted(f"TEXCOORD_{n}" for n in sets)
            if names != want:
                fail(f"{label}: {leaf} has {names}, expected {want}")
                continue
            corners = indices(doc, buffer, p["indices"])
            coords = {n: accessor_floats(doc, buffer, p["attributes"][f"TEXCOORD_{n}"]) for n in sets}
            for n, expected in sets.items():
                if expected == ZEROS:
                    if any(x != 0 for i in corners for x in coords[n][i]):
                        fail(f"{label}: {leaf}'s TEXCOORD_{n} (a set it lacks) is not all zeros")
                    continue
                uvs = [(coords[n][i][0], 1 - coords[n][i][1]) for i in corners]
                got = (min(u for u, v in uvs), max(u for u, v in uvs), min(v for u, v in uvs), max(v for u, v in uvs))
                if not all(near(g, e) for g, e in zip(got, expected)):
                    fail(f"{label}: {leaf} set {n} uv range {tuple(round(g, 6) for g in got)}, expected {expected}")
            if leaf == "L1":
                for i in corners:
                    (u0, v0), (u1, v1) = coords[0][i], coords[1][i]
                    if not (near(u1, 2 * u0) and near(1 - v1, (1 - v0) / 2)):
                        fail(f"{label}: L1 vertex {i}: set 1 {(u1, 1 - v1)} is not (2 u0, v0 / 2) of set 0 {(u0, 1 - v0)}")
                        break
            m = doc["materials"][p["material"]]
            got_normal = None if "normalTexture" not in m else m["normalTexture"].get("texCoord", 0)
            if got_normal != normal:
                fail(f"{label}: {leaf}'s normal map texCoord {got_normal}, expected {normal}")
            if normal == 0 and "texCoord" in m["normalTexture"]:
                fail(f"{label}: {leaf}'s normal map on set 0 writes texCoord (glTF's default)")
    reports = {}
    for node in doc["nodes"]:
        for key, collection in node.get("extras", {}).get("reports", {}).items():
            reports.setdefault(key, []).extend(collection["values"])
    for key, expected in UV_LAYER_REPORTS.items():
        if reports.get(key) is None or len(reports[key]) != 1 or not near(reports[key][0], expected):
            fail(f"{label}: report {key} {reports.get(key)}, expected [{expected}]")


def check_mtl(path, label):
    text = open(path).read()
    blocks = {}
    for block in text.split("\nnewmtl ")[1:]:
        lines = block.splitlines()
        blocks[lines[0]] = dict(l.split(" ", 1) for l in lines[1:] if " " in l)
    for leaf, (d, pr, pm) in MTL.items():
        found = [b for b in blocks.values() if b.get("d") == d and b.get("Pr") == pr and b.get("Pm") == pm]
        if not found:
            fail(f"{label}: no material with d {d} Pr {pr} Pm {pm} (for {leaf}) in the .mtl")
        elif leaf == "M5" and not any("norm" in b and "map_Kd" in b for b in found):
            fail(f"{label}: the .mtl's {leaf} material has no `norm` and `map_Kd`")


def main():
    fgsg, root = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    here = os.path.join(root, "tests", "cga", "materials")
    lots = os.path.join(root, "tests", "cga", "corpus", "lots")
    validator = os.path.join(root, "scripts", "validate-gltf.js")
    with tempfile.TemporaryDirectory() as tmp:
        os.symlink(os.path.join(root, "examples", "textures"), os.path.join(tmp, "textures"))
        for name, lot in (("materials", "rect20x10"), ("uv_operations", "street40x12"), ("uv_delete", "street40x12"),
                          ("uv_sets", "street40x12"), ("uv_layers", "street40x12"), ("uv_world", "square10")):
            for ext in ("cga", "fgsg"):
                grammar = os.path.join(tmp, f"{name}.{ext}")
                shutil.copy(os.path.join(here, f"{name}.{ext}"), grammar)
                outputs = {}
                for engine in ("interp", "jit"):
                    label = f"{name}.{ext} ({engine})"
                    out = os.path.join(tmp, f"{name}_{ext}_{engine}.gltf")
                    obj = os.path.join(tmp, f"{name}_{ext}_{engine}.obj")
                    for target, extra in ((out, ["--instancing", "off"]), (obj, [])):
                        run = subprocess.run([fgsg, "run", grammar, "--lots", os.path.join(lots, lot + ".geojson"),
                                              "-o", target, "--group-by", "symbol", f"--engine={engine}", "-q"] + extra,
                                             capture_output=True, text=True, timeout=120)
                        if run.returncode != 0:
                            fail(f"{label}: fgsg run exited {run.returncode}: {run.stderr.strip()}")
                            break
                    else:
                        outputs[engine] = open(out, "rb").read() + open(obj[:-4] + ".mtl", "rb").read()
                        v = subprocess.run(["node", validator, "--strict", out], capture_output=True, text=True)
                        if v.returncode != 0 or ": 0 errors, 0 warnings" not in v.stdout + v.stderr:
                            fail(f"{label}: gltf-validator: {(v.stdout + v.stderr).strip()[-2000:]}")
                        doc = json.load(open(out))
                        buffer = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
                        if name == "materials":
                            check_materials(doc, label)
                            check_mtl(obj[:-4] + ".mtl", label)
                        elif name == "uv_layers":
                            check_uv_layers(doc, buffer, label)
                        else:
                            check_uvs(doc, buffer, label,
                                      {"uv_operations": "U", "uv_delete": "D", "uv_sets": "S"}.get(name, "W"))
                        if name == "uv_delete":
                            check_no_uvs(doc, obj, label)
                        if name == "uv_sets":
                            check_no_uvs_sets(doc, label)
                if len(outputs) == 2 and outputs["interp"] != outputs["jit"]:
                    fail(f"{name}.{ext}: the interpreter's and the JIT's files differ")
                if not failures:
                    print(f"PASS {name}.{ext} (interp, jit)")
        # A flattened file has no place for the finishes: R031 says so (a warning, exit 0).
        for engine in ("interp", "jit"):
            run = subprocess.run([fgsg, "run", os.path.join(tmp, "materials.cga"), "--lots",
                                  os.path.join(lots, "rect20x10.geojson"), "-o", os.path.join(tmp, "flat.obj"),
                                  f"--engine={engine}"], capture_output=True, text=True, timeout=120)
            if run.returncode != 0 or "materials.cga: warning[R031]" not in run.stderr:
                fail(f"flattened materials.cga ({engine}): exit {run.returncode}, no R031: {run.stderr.strip()}")
        # uv sets 1..9 are in the glTF scene alone: an OBJ, grouped or not, and a flattened glb
        # keep set 0 and say so with R033 (a warning, exit 0); the glTF scene says nothing.
        for target, extra, warned in (("flat.obj", [], True), ("grouped.obj", ["--group-by", "symbol"], True),
                                      ("flat.glb", ["--instancing", "off", "--group-by", "none"], True),
                                      ("scene.glb", [], False)):
            for engine in ("interp", "jit"):
                run = subprocess.run([fgsg, "run", os.path.join(tmp, "uv_layers.cga"), "--lots",
                                      os.path.join(lots, "street40x12.geojson"), "-o", os.path.join(tmp, target),
                                      f"--engine={engine}"] + extra, capture_output=True, text=True, timeout=120)
                if run.returncode != 0 or ("uv_layers.cga: warning[R033]" in run.stderr) != warned:
                    fail(f"uv_layers.cga -o {target} ({engine}): exit {run.returncode}, R033 expected {warned}: "
                         f"{run.stderr.strip()}")
        for file, source, expected in ERRORS:
            path = os.path.join(tmp, file)
            open(path, "w").write(source)
            for engine in ("interp", "jit"):
                run = subprocess.run([fgsg, "run", path, "--lots", os.path.join(lots, "rect20x10.geojson"), "-o",
                                      os.path.join(tmp, "error.glb"), f"--engine={engine}"],
                                     capture_output=True, text=True, timeout=120)
                if run.returncode != 1 or expected not in run.stderr:
                    fail(f"{file} ({engine}): exit {run.returncode}, expected {expected}: {run.stderr.strip()}")
        if not failures:
            print(f"PASS {len(ERRORS)} located errors (interp, jit)")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

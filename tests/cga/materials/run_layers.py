#!/usr/bin/env python3
"""CityEngine's texture layers besides the colour and normal maps (issue #44) read back from
the glTF scenes and .mtl files fgsg writes.

run_layers.py FGSG ROOT: draws the layer images (maps/*.png) beside copies of layers.cga /
layers.fgsg, runs each on lots/rect20x10 with --engine=interp and --engine=jit as a .gltf
scene (--instancing off --group-by symbol) and as a grouped OBJ; requires the two engines'
files to be the same bytes, the Khronos validator to find no errors and no warnings, each
leaf's texture slots, texCoords and factors as layers.cga's comment computes them by hand,
the packed metallic-roughness image's pixels, the .mtl statements, R034 where a layer has no
place in the output; then the located errors of ERRORS. Exits 1 on any failure."""
import base64
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

from gltf_scene import leaves

failures = []


def fail(what):
    failures.append(what)
    print("FAIL", what)


def png(width, height, channels, rows):
    """An 8-bit PNG (grey or RGB) of `rows` (each a list of channel values), unfiltered."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    raw = b"".join(b"\0" + bytes(row) for row in rows)
    header = struct.pack(">IIBBBBB", width, height, 8, {1: 0, 3: 2}[channels], 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def decode_png(data):
    """(width, height, channels, rows) of an 8-bit grey / RGB / RGBA PNG, any row filters."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    at, idat = 8, b""
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
            assert depth == 8, "not 8 bits"
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[color]
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], [0] * width * channels
    for y in range(height):
        kind, line = raw[y * (stride + 1)], list(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


ROUGH = [[10, 60], [110, 160]]  # 2 x 2 grey
AO = [[200, 100], [50, 25]]  # 2 x 2 grey
METAL_BLUE = [[20 + 10 * x + 50 * y for x in range(4)] for y in range(4)]  # 4 x 4, red and green 0


def draw_maps(folder):
    os.makedirs(folder)
    images = {
        "rough.png": png(2, 2, 1, ROUGH),
        "metal.png": png(4, 4, 3, [sum(([0, 0, b] for b in row), []) for row in METAL_BLUE]),
        "glow.png": png(2, 2, 3, [[255, 200, 0] * 2] * 2),
        "ao.png": png(2, 2, 1, AO),
        "bump.png": png(2, 2, 1, [[0, 255], [255, 0]]),
    }
    for name, data in images.items():
        open(os.path.join(folder, name), "wb").write(data)
    return images


def image_bytes(doc, buffer, texture):
    view = doc["bufferViews"][doc["images"][doc["textures"][texture]["source"]]["bufferView"]]
    return buffer[view.get("byteOffset", 0):view.get("byteOffset", 0) + view["byteLength"]]


def slot(material, name):
    """(texture index, texCoord) of a material's texture slot, or None."""
    t = material.get(name, material["pbrMetallicRoughness"].get(name))
    return None if t is None else (t["index"], t.get("texCoord", 0))


def check_gltf(doc, buffer, images, label):
    by_leaf = leaves(doc)
    mats = {}
    for leaf in ("P1", "P2", "P3", "P4", "P5"):
        found = {p.get("material") for p in by_leaf.get(leaf, [])}
        if len(found) != 1:
            fail(f"{label}: {leaf} has materials {sorted(found)}, one expected")
            return
        mats[leaf] = doc["materials"][found.pop()]
    image_of = lambda t: image_bytes(doc, buffer, t)
    # P1: every layer on set 0.
    m = mats["P1"]
    for name, source in (("occlusionTexture", "ao.png"), ("emissiveTexture", "glow.png")):
        s = slot(m, name)
        if s is None or s[1] != 0 or "texCoord" in m[name] or image_of(s[0]) != images[source]:
            fail(f"{label}: P1's {name} {m.get(name)}: expected {source} on set 0 (no texCoord)")
    if m.get("emissiveFactor") != [0.5, 0, 0]:
        fail(f"{label}: P1's emissiveFactor {m.get('emissiveFactor')}, expected [0.5, 0, 0]")
    s = slot(m, "metallicRoughnessTexture")
    if s is None or s[1] != 0:
        fail(f"{label}: P1 has no metallicRoughnessTexture on set 0: {m['pbrMetallicRoughness']}")
    else:
        w, h, c, rows = decode_png(image_of(s[0]))
        expected = [[(255, ROUGH[y // 2][x // 2], METAL_BLUE[y][x]) for x in range(4)] for y in range(4)]
        got = [[tuple(rows[y][c * x:c * x + 3]) for x in range(w)] for y in range(h)]
        if (w, h, c) != (4, 4, 3) or got != expected:
            fail(f"{label}: P1's packed metallic-roughness image {w} x {h} x {c} {got}, expected {expected}")
    if slot(m, "baseColorTexture") is None or "normalTexture" in m:
        fail(f"{label}: P1's base colour / normal slots {m}")
    # P2: the emissive map on set 6, the roughness map on set 8, metallic 255 (no map).
    m = mats["P2"]
    s = slot(m, "emissiveTexture")
    if s is None or s[1] != 6 or image_of(s[0]) != images["glow.png"] or m.get("emissiveFactor") != [1, 1, 1]:
        fail(f"{label}: P2's emissive {m.get('emissiveTexture')} {m.get('emissiveFactor')}, expected texCoord 6, factor 1 1 1")
    s = slot(m, "metallicRoughnessTexture")
    if s is None or s[1] != 8:
        fail(f"{label}: P2's metallicRoughnessTexture {s}, expected texCoord 8")
    else:
        w, h, c, rows = decode_png(image_of(s[0]))
        got = [tuple(rows[y][c * x:c * x + 3]) for y in range(h) for x in range(w)]
        if (w, h) != (2, 2) or got != [(255, ROUGH[y][x], 255) for y in range(2) for x in range(2)]:
            fail(f"{label}: P2's packed image {w} x {h} {got}")
    if not m["name"].endswith("_uv68"):
        fail(f"{label}: P2's material is named {m['name']}, expected ..._uv68")
    prims = by_leaf["P2"]
    if any(k not in p["attributes"] for p in prims for k in ("TEXCOORD_6", "TEXCOORD_8")):
        fail(f"{label}: P2 lacks TEXCOORD_6 or TEXCOORD_8")
    # P3: no colour map: occlusion on its own set 7, the emissive map dropped, the opacity map
    # a white base colour texture with its alpha, on set 4.
    m = mats["P3"]
    if slot(m, "occlusionTexture") is None or slot(m, "occlusionTexture")[1] != 7 or "emissiveTexture" in m \
            or "emissiveFactor" in m or m.get("alphaMode") != "BLEND":
        fail(f"{label}: P3's material {m}: expected occlusionTexture on set 7, no emissive, alphaMode BLEND")
    s = slot(m, "baseColorTexture")
    if s is None or s[1] != 4:
        fail(f"{label}: P3's baseColorTexture {s}, expected the opacity map on texCoord 4")
    else:
        w, h, c, rows = decode_png(image_of(s[0]))
        got = [tuple(rows[y][c * x:c * x + c]) for y in range(h) for x in range(w)]
        if (w, h, c) != (2, 2, 4) or got != [(255, 255, 255, AO[y][x]) for y in range(2) for x in range(2)]:
            fail(f"{label}: P3's base colour image {w} x {h} x {c} {got}")
    # P4: the opacity map in the base colour image's alpha, brick.png's colours kept.
    m = mats["P4"]
    s = slot(m, "baseColorTexture")
    if s is None or s[1] != 0 or m.get("alphaMode") != "BLEND":
        fail(f"{label}: P4's baseColorTexture {s} alphaMode {m.get('alphaMode')}, expected set 0, BLEND")
    else:
        w, h, c, rows = decode_png(image_of(s[0]))
        bw, bh, bc, brick = decode_png(images["brick"])
        expected = [brick[y][bc * x:bc * x + 3] + [AO[y * 2 // bh][x * 2 // bw]] for y in range(bh) for x in range(bw)]
        got = [rows[y][c * x:c * x + c] for y in range(h) for x in range(w)]
        if (w, h, c) != (bw, bh, 4) or got != expected:
            fail(f"{label}: P4's base colour image {w} x {h} x {c} is not brick.png with ao.png's alpha")
    # P4's specular map: KHR_materials_specular's specularColorTexture, on set 0.
    specular = mats["P4"].get("extensions", {}).get("KHR_materials_specular", {}).get("specularColorTexture")
    if specular is None or "texCoord" in specular or image_of(specular["index"]) != images["bump.png"] \
            or "KHR_materials_specular" not in doc.get("extensionsUsed", []):
        fail(f"{label}: P4's specular map {specular}, extensionsUsed {doc.get('extensionsUsed')}: expected bump.png "
             "as KHR_materials_specular's specularColorTexture on set 0")
    # P4 and P5: no other layer textures; P4's bump and dirt maps have no glTF slot.
    for leaf in ("P4", "P5"):
        m = mats[leaf]
        extra = [k for k in ("occlusionTexture", "emissiveTexture", "normalTexture", "emissiveFactor") if k in m]
        if extra or "metallicRoughnessTexture" in m["pbrMetallicRoughness"]:
            fail(f"{label}: {leaf} has {extra} {m['pbrMetallicRoughness']}")
    # (named brick_ffffff_N: the materials before it took the plain name's variants)
    if not mats["P5"]["name"].startswith("brick_ffffff") or set(mats["P5"]) != {"doubleSided", "name", "pbrMetallicRoughness"} \
            or set(mats["P5"]["pbrMetallicRoughness"]) != {"baseColorTexture", "metallicFactor", "roughnessFactor"}:
        fail(f"{label}: P5's material {mats['P5']}, expected the plain brick material")
    elif image_of(slot(mats["P5"], "baseColorTexture")[0]) != images["brick"]:
        fail(f"{label}: P5's base colour image is not brick.png as it is")


def check_mtl(path, label):
    blocks = []
    for block in open(path).read().split("\nnewmtl ")[1:]:
        blocks.append(dict(l.split(" ", 1) for l in block.splitlines()[1:] if " " in l))
    want = [
        ("P1", {"map_Pr": "maps/rough.png", "map_Pm": "maps/metal.png", "map_Ke": "maps/glow.png", "Ke": "0.5 0 0"}),
        ("P2", {"map_Pr": "maps/rough.png", "map_Ke": "maps/glow.png"}),
        ("P4", {"map_bump": "maps/bump.png", "map_Ks": "maps/bump.png", "map_d": "maps/ao.png"}),
    ]
    for leaf, lines in want:
        if not any(all(b.get(k, "").endswith(v) for k, v in lines.items()) and "map_Kd" in b for b in blocks):
            fail(f"{label}: no .mtl material with {lines} (for {leaf})")
    if any("map_ao" in b or "map_dirt" in b for b in blocks):
        fail(f"{label}: the .mtl names an occlusion or dirt map")


# Located diagnostics, both engines: (file name, source, the diagnostic's start, exit status).
# A missing image in .cga is CityEngine's warning (the layer skipped), in fgsg an error.
ERRORS = [
    ("b1.cga", 'version "2023.0"\n@StartRule\nLot --> set(material.glossmap, "maps/ao.png") X.\n',
     "b1.cga:3:13: error[E801]", 1),
    ("b2.fgsg", 'axiom: Lot;\nLot ~> Material("glossmap", "maps/ao.png") X;\n', "b2.fgsg:2:17: error[E028]", 1),
    ("b3.cga", 'version "2023.0"\n@StartRule\nLot --> set(material.emissivemap, "maps/none.png") X.\n',
     "b3.cga:3:9: warning[W801]: the texture 'maps/none.png' is not found", 0),
    ("b4.fgsg", 'axiom: Lot;\nLot ~> Material("occlusionmap", "maps/none.png") X;\n', "b4.fgsg:2:8: error[R003]", 1),
]


def main():
    fgsg, root = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    here = os.path.join(root, "tests", "cga", "materials")
    lot = os.path.join(root, "tests", "cga", "corpus", "lots", "rect20x10.geojson")
    validator = os.path.join(root, "scripts", "validate-gltf.js")
    with tempfile.TemporaryDirectory() as tmp:
        os.symlink(os.path.join(root, "examples", "textures"), os.path.join(tmp, "textures"))
        images = draw_maps(os.path.join(tmp, "maps"))
        images["brick"] = open(os.path.join(root, "examples", "textures", "brick.png"), "rb").read()
        for ext in ("cga", "fgsg"):
            grammar = os.path.join(tmp, f"layers.{ext}")
            shutil.copy(os.path.join(here, f"layers.{ext}"), grammar)
            outputs = {}
            for engine in ("interp", "jit"):
                label = f"layers.{ext} ({engine})"
                out, obj = os.path.join(tmp, f"{ext}_{engine}.gltf"), os.path.join(tmp, f"{ext}_{engine}.obj")
                runs = {}
                for target, extra in ((out, ["--instancing", "off"]), (obj, [])):
                    runs[target] = subprocess.run([fgsg, "run", grammar, "--lots", lot, "-o", target, "--group-by",
                                                   "symbol", f"--engine={engine}"] + extra,
                                                  capture_output=True, text=True, timeout=120)
                if any(r.returncode != 0 for r in runs.values()):
                    fail(f"{label}: fgsg run: {[r.stderr.strip() for r in runs.values()]}")
                    continue
                r034 = {t: [l for l in r.stderr.splitlines() if "warning[R034]" in l] for t, r in runs.items()}
                gltf_warning = r034[out] == [l for l in r034[out]
                                             if "warning[R034]: material.bumpmap, material.dirtmap not in" in l] != []
                obj_warning = r034[obj] == [l for l in r034[obj] if "warning[R034]: material.dirtmap, "
                                            "material.occlusionmap not in" in l] != []
                if not gltf_warning or not obj_warning:
                    fail(f"{label}: R034 expected for the glTF's bump and dirt maps and the OBJ's dirt map: "
                         f"{runs[out].stderr.strip()} / {runs[obj].stderr.strip()}")
                outputs[engine] = open(out, "rb").read() + open(obj[:-4] + ".mtl", "rb").read()
                v = subprocess.run(["node", validator, "--strict", out], capture_output=True, text=True)
                if v.returncode != 0 or ": 0 errors, 0 warnings" not in v.stdout + v.stderr:
                    fail(f"{label}: gltf-validator: {(v.stdout + v.stderr).strip()[-2000:]}")
                doc = json.load(open(out))
                buffer = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
                check_gltf(doc, buffer, images, label)
                check_mtl(obj[:-4] + ".mtl", label)
            if len(outputs) == 2 and outputs["interp"] != outputs["jit"]:
                fail(f"layers.{ext}: the interpreter's and the JIT's files differ")
            if not failures:
                print(f"PASS layers.{ext} (interp, jit)")
        for file, source, expected, status in ERRORS:
            path = os.path.join(tmp, file)
            open(path, "w").write(source)
            for engine in ("interp", "jit"):
                run = subprocess.run([fgsg, "run", path, "--lots", lot, "-o", os.path.join(tmp, "error.glb"),
                                      f"--engine={engine}"], capture_output=True, text=True, timeout=120)
                if run.returncode != status or expected not in run.stderr:
                    fail(f"{file} ({engine}): exit {run.returncode}, expected {expected}: {run.stderr.strip()}")
        if not failures:
            print(f"PASS {len(ERRORS)} located diagnostics (interp, jit)")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""An independent reader of `fgsg run --quantize` (issue #45): checks a quantized glTF
scene against the float scene of the same run, vertex by vertex.

  gltf_quantized_check.py QUANTIZED.glb FLOAT.glb [--position-tolerance T]

Both files are decoded here (gltf_scene_check.py's reader: normalized integers as glTF
decodes them, node transforms, EXT_mesh_gpu_instancing); per start node and mesh name the
world positions of every vertex, placed by every node and instance, must lie within T
(metres, each axis) of the float file's; normals within 1e-4; TEXCOORD_0, scaled by the
material's KHR_texture_transform, must differ from the float file's by whole tiles (the
same for a whole primitive) plus at most half a step (the coarsest 1/4096 of a tile). KHR_mesh_quantization must be in
extensionsUsed and extensionsRequired. Prints what it compared and the largest
differences; exits 1 on the first mismatch."""
import argparse
import collections
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_scene_check import accessor, fail, load, node_matrix, trs_matrix  # noqa: E402


def placed_vertices(doc, bin_chunk):
    """Per (start node name, mesh name): the list, in the node tree's order, of what each
    node placing that mesh holds: world positions (each instance's), normals (rotated, not
    normalized back: compared per placement), and per primitive its TEXCOORD_0 scaled by
    the material's texture transform."""
    out = collections.defaultdict(list)
    nodes = doc["nodes"]

    def visit(i, parent, start):
        node = nodes[i]
        world = parent @ node_matrix(node)
        if "mesh" in node:
            mesh = doc["meshes"][node["mesh"]]
            ext = node.get("extensions", {}).get("EXT_mesh_gpu_instancing")
            mats = [world]
            if ext:
                a = ext["attributes"]
                t = accessor(doc, bin_chunk, a["TRANSLATION"]).astype(float)
                r = accessor(doc, bin_chunk, a["ROTATION"]).astype(float)
                s = accessor(doc, bin_chunk, a["SCALE"]).astype(float) if "SCALE" in a else np.ones((len(t), 3))
                mats = [world @ trs_matrix(t[k], r[k], s[k]) for k in range(len(t))]
            for p in mesh["primitives"]:
                pos = accessor(doc, bin_chunk, p["attributes"]["POSITION"]).astype(float)
                h = np.hstack([pos, np.ones((len(pos), 1))])
                # Texture coordinates only where the material samples them.
                uv = None
                material = doc["materials"][p["material"]] if "material" in p else {}
                info = material.get("pbrMetallicRoughness", {}).get("baseColorTexture")
                if "TEXCOORD_0" in p["attributes"] and info is not None:
                    uv = accessor(doc, bin_chunk, p["attributes"]["TEXCOORD_0"]).astype(float)
                    scale = info.get("extensions", {}).get("KHR_texture_transform", {}).get("scale", [1, 1])
                    uv = uv * np.asarray(scale, dtype=float)
                normal = None
                if "NORMAL" in p["attributes"]:
                    normal = accessor(doc, bin_chunk, p["attributes"]["NORMAL"]).astype(float)
                for m in mats:
                    out[(start, mesh.get("name"))].append({
                        "positions": (h @ m.T)[:, :3],
                        "normals": None if normal is None else normal,
                        "uv": uv,
                    })
        for c in node.get("children", []):
            visit(c, world, start)

    for root in doc["scenes"][doc.get("scene", 0)].get("nodes", []):
        visit(root, np.eye(4), nodes[root].get("name"))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("quantized")
    ap.add_argument("float")
    ap.add_argument("--position-tolerance", type=float, default=5e-4)
    args = ap.parse_args()
    qdoc, qbin = load(args.quantized)
    fdoc, fbin = load(args.float)
    for key in ("extensionsUsed", "extensionsRequired"):
        if "KHR_mesh_quantization" not in qdoc.get(key, []):
            fail(f"KHR_mesh_quantization is not in {key}")
    short = sum(1 for a in qdoc["accessors"] if a["componentType"] in (5122, 5123) and a["type"] != "SCALAR")
    if short == 0:
        fail("no 16-bit vertex attribute in the quantized file")
    q, f = placed_vertices(qdoc, qbin), placed_vertices(fdoc, fbin)
    if sorted(q) != sorted(f):
        fail(f"the files place other meshes: {sorted(set(q) ^ set(f))[:5]}")
    worst_pos = worst_normal = worst_uv = 0.0
    vertices = 0
    for key in sorted(f):
        if len(q[key]) != len(f[key]):
            fail(f"{key}: {len(q[key])} placed primitives, the float file {len(f[key])}")
        for a, b in zip(q[key], f[key]):
            if a["positions"].shape != b["positions"].shape:
                fail(f"{key}: {len(a['positions'])} vertices, the float file {len(b['positions'])}")
            vertices += len(b["positions"])
            d = np.max(np.abs(a["positions"] - b["positions"]), initial=0)
            worst_pos = max(worst_pos, d)
            if not d <= args.position_tolerance:
                fail(f"{key}: a vertex is {d} m off the float file's (> {args.position_tolerance})")
            if (a["normals"] is None) != (b["normals"] is None):
                fail(f"{key}: normals in one file only")
            if b["normals"] is not None:
                worst_normal = max(worst_normal, np.max(np.abs(a["normals"] - b["normals"]), initial=0))
            if (a["uv"] is None) != (b["uv"] is None):
                fail(f"{key}: texture coordinates in one file only")
            if b["uv"] is not None and len(b["uv"]):
                tiles = a["uv"] - b["uv"]
                whole = np.round(tiles)
                if np.any(whole != whole[0]):
                    fail(f"{key}: texture coordinates moved by different whole tiles in one primitive")
                worst_uv = max(worst_uv, np.max(np.abs(tiles - whole)))
    if worst_normal > 1e-4:
        fail(f"a normal is {worst_normal} off the float file's")
    if worst_uv > 1 / 8192:  # half the coarsest step, 1/4096 of a tile
        fail(f"a texture coordinate is {worst_uv} of a tile off the float file's")
    a, b = os.path.getsize(args.quantized), os.path.getsize(args.float)
    print(f"compared {vertices} placed vertices: positions within {worst_pos * 1000:.3f} mm "
          f"(tolerance {args.position_tolerance * 1000:.3f} mm), normals within {worst_normal:.2g}, "
          f"texture coordinates within {worst_uv:.2g} tile")
    print(f"bytes: quantized {a}, float {b}, ratio {a / b:.4f}")


if __name__ == "__main__":
    main()

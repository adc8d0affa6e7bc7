#!/usr/bin/env python3
"""An independent reader of fgsg's structured glTF (issue #45): parses the .glb (or .gltf)
itself, places every vertex in world space through the node tree and
EXT_mesh_gpu_instancing, and checks the scene against the flattened output of the same run
and its --instances JSON.

  gltf_scene_check.py SCENE.glb FLAT.glb INSTANCES.json [--starts N] [--start-names FILE.geojson]
                      [--tolerance T] [--max-ratio R]

Prints the facts it checked and the byte ratio; exits 1 on the first mismatch."""
import argparse
import base64
import collections
import json
import math
import os
import struct
import sys

import numpy as np

COMPONENTS = {5126: np.float32, 5125: np.uint32, 5123: np.uint16, 5122: np.int16, 5121: np.uint8, 5120: np.int8}
WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def load(path):
    data = open(path, "rb").read()
    if data[:4] == b"glTF":
        magic, version, length = struct.unpack_from("<4sII", data, 0)
        if version != 2 or length != len(data):
            fail(f"{path}: GLB header says version {version}, length {length} (file {len(data)})")
        json_len, json_type = struct.unpack_from("<I4s", data, 12)
        if json_type != b"JSON":
            fail(f"{path}: first chunk is not JSON")
        doc = json.loads(data[20:20 + json_len])
        at = 20 + json_len
        bin_chunk = b""
        if at < len(data):
            bin_len, bin_type = struct.unpack_from("<I4s", data, at)
            if bin_type != b"BIN\0":
                fail(f"{path}: second chunk is not BIN")
            bin_chunk = data[at + 8:at + 8 + bin_len]
        return doc, bin_chunk
    doc = json.loads(data)
    bin_chunk = b""
    if doc.get("buffers"):
        uri = doc["buffers"][0]["uri"]
        bin_chunk = base64.b64decode(uri.split(",", 1)[1])
    return doc, bin_chunk


def accessor(doc, bin_chunk, index):
    a = doc["accessors"][index]
    v = doc["bufferViews"][a["bufferView"]]
    dtype = COMPONENTS[a["componentType"]]
    width = WIDTH[a["type"]]
    start = v.get("byteOffset", 0) + a.get("byteOffset", 0)
    count = a["count"]
    element = width * np.dtype(dtype).itemsize
    stride = v.get("byteStride", element)
    if "byteStride" in v and (stride < element or stride % 4):
        fail(f"buffer view {a['bufferView']}: byteStride {stride} for elements of {element} bytes")
    if start % np.dtype(dtype).itemsize:
        fail(f"accessor {index} is not aligned to its component")
    end = start + (count - 1) * stride + element
    if end > v.get("byteOffset", 0) + v["byteLength"]:
        fail(f"accessor {index} runs past its buffer view")
    rows = np.lib.stride_tricks.as_strided(np.frombuffer(bin_chunk[start:end] + b"\0" * (stride - element), dtype=np.uint8),
                                           shape=(count, element), strides=(stride, 1))
    arr = np.ascontiguousarray(rows).view(dtype).reshape(count, width)
    if a.get("normalized"):  # glTF's decoding of normalized integers
        arr = np.maximum(arr.astype(float) / np.iinfo(dtype).max, -1.0)
    return arr if width > 1 else arr[:, 0]


def trs_matrix(t, r, s):
    x, y, z, w = [float(c) for c in r]
    rot = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                    [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                    [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    m = np.eye(4)
    m[:3, :3] = rot * np.asarray(s, dtype=float)[None, :]
    m[:3, 3] = t
    return m


def node_matrix(node):
    if "matrix" in node:
        return np.array(node["matrix"], dtype=float).reshape(4, 4).T
    return trs_matrix(node.get("translation", [0, 0, 0]), node.get("rotation", [0, 0, 0, 1]),
                      node.get("scale", [1, 1, 1]))


def used_positions(doc, bin_chunk, mesh_index):
    """The positions each primitive's indices use (the flattened writer drops the rest)."""
    out = []
    for p in doc["meshes"][mesh_index]["primitives"]:
        pos = accessor(doc, bin_chunk, p["attributes"]["POSITION"]).astype(float)
        if "indices" in p:
            pos = pos[np.unique(accessor(doc, bin_chunk, p["indices"]))]
        out.append(pos)
    return np.concatenate(out) if out else np.zeros((0, 3))


def world_bounds(doc, bin_chunk):
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    instanced = collections.Counter()  # asset -> instances, read from the accessors
    nodes = doc.get("nodes", [])
    stack = [(i, np.eye(4)) for i in doc["scenes"][doc.get("scene", 0)].get("nodes", [])]
    while stack:
        i, parent = stack.pop()
        node = nodes[i]
        world = parent @ node_matrix(node)
        if "mesh" in node:
            local = used_positions(doc, bin_chunk, node["mesh"])
            ext = node.get("extensions", {}).get("EXT_mesh_gpu_instancing")
            if ext:
                a = ext["attributes"]
                t = accessor(doc, bin_chunk, a["TRANSLATION"]).astype(float)
                r = accessor(doc, bin_chunk, a["ROTATION"]).astype(float)
                # SCALE left out: 1 (the instances' one scale is then in the mesh).
                s = accessor(doc, bin_chunk, a["SCALE"]).astype(float) if "SCALE" in a else np.ones((len(t), 3))
                # Colours per instance only where a group's colours vary (else the material's).
                c = accessor(doc, bin_chunk, a["_COLOR_0"]) if "_COLOR_0" in a else t
                if not (len(t) == len(r) == len(s) == len(c)):
                    fail(f"node {i}: instancing accessors of different counts")
                norms = np.linalg.norm(r, axis=1)
                # Normalized 16-bit components are unit to their step (1/32767).
                if np.max(np.abs(norms - 1)) > (1e-4 if doc["accessors"][a["ROTATION"]].get("normalized") else 1e-5):
                    fail(f"node {i}: a ROTATION is not a unit quaternion")
                instanced[node["extras"]["asset"]] += len(t)
                mats = [world @ trs_matrix(t[k], r[k], s[k]) for k in range(len(t))]
            else:
                mats = [world]
                if "extras" in node and "asset" in node["extras"]:
                    instanced[node["extras"]["asset"]] += 1
            h = np.hstack([local, np.ones((len(local), 1))])
            for m in mats:
                w = (h @ m.T)[:, :3]
                if len(w):
                    lo, hi = np.minimum(lo, w.min(0)), np.maximum(hi, w.max(0))
        for c in node.get("children", []):
            stack.append((c, world))
    return lo, hi, instanced


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("flat")
    ap.add_argument("instances")
    ap.add_argument("--starts", type=int, help="expected number of start-shape nodes")
    ap.add_argument("--start-names", help="a GeoJSON file whose feature ids name the start nodes, in order")
    ap.add_argument("--tolerance", type=float, default=1e-4)
    ap.add_argument("--expect-instanced", action="store_true", help="some instances must be instanced")
    ap.add_argument("--max-ratio", type=float, help="the scene's bytes over the flattened file's at most this")
    args = ap.parse_args()

    doc, bin_chunk = load(args.scene)
    flat_doc, flat_bin = load(args.flat)
    listed = json.load(open(args.instances))
    per_asset = collections.Counter(i["asset"] for i in listed["instances"])

    if any("EXT_mesh_gpu_instancing" in n.get("extensions", {}) for n in doc.get("nodes", [])):
        if "EXT_mesh_gpu_instancing" not in doc.get("extensionsUsed", []):
            fail("EXT_mesh_gpu_instancing is used but not in extensionsUsed")

    roots = doc["scenes"][0].get("nodes", [])
    starts = [doc["nodes"][r] for r in roots if doc["nodes"][r].get("name") != "(surface and lines)"]
    if args.starts is not None and len(starts) != args.starts:
        fail(f"{len(starts)} start-shape nodes, expected {args.starts}")
    if args.start_names:
        features = json.load(open(args.start_names))["features"]
        names = [str(f.get("id", f"feature {k}")) for k, f in enumerate(features)]
        got = [s["name"] for s in starts]
        if got != names[:len(got)] or len(got) != len(names):
            fail(f"start nodes are named {got[:3]}..., expected {names[:3]}...")
        for s, f in zip(starts, features):
            for key, value in f.get("properties", {}).items():
                if isinstance(value, (int, float, str)) and not isinstance(value, bool):
                    if s["extras"].get("properties", {}).get(key) != value:
                        fail(f"start node {s['name']}: extras.properties.{key} is not {value!r}")
    total = sum(doc["nodes"][r]["extras"]["instances"] for r in roots)
    if total != len(listed["instances"]):
        fail(f"the start nodes hold {total} instances, --instances lists {len(listed['instances'])}")

    lo, hi, instanced = world_bounds(doc, bin_chunk)
    baked = collections.Counter()
    for n in doc.get("nodes", []):
        for asset, count in n.get("extras", {}).get("baked", {}).items():
            baked[asset] += count
    for asset in sorted(set(per_asset) | set(instanced) | set(baked)):
        got = instanced[asset] + baked[asset]
        if got != per_asset[asset]:
            fail(f"asset {asset}: {instanced[asset]} instanced + {baked[asset]} baked, --instances lists {per_asset[asset]}")
        print(f"asset {asset}: {per_asset[asset]} instances ({instanced[asset]} instanced, {baked[asset]} baked)")
    if args.expect_instanced and sum(instanced.values()) == 0:
        fail("nothing is instanced")

    flo, fhi, _ = world_bounds(flat_doc, flat_bin)
    diff = max(np.max(np.abs(lo - flo)), np.max(np.abs(hi - fhi)))
    print(f"bounds {lo.tolist()} .. {hi.tolist()}; flattened differs by {diff:.3g}")
    if not diff <= args.tolerance:
        fail(f"the world bounds differ from the flattened output's by {diff} (> {args.tolerance})")
    a, b = os.path.getsize(args.scene), os.path.getsize(args.flat)
    print(f"bytes: scene {a}, flattened {b}, ratio {a / b:.4f}")
    if args.max_ratio is not None and not a / b <= args.max_ratio:
        fail(f"the scene is {a / b:.4f} of the flattened bytes (> {args.max_ratio})")
    print(f"ok: {len(starts)} start nodes, {len(listed['instances'])} instances")


if __name__ == "__main__":
    main()

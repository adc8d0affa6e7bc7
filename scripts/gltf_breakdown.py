#!/usr/bin/env python3
"""Where a .glb's bytes go: the JSON chunk, and the BIN chunk by what its accessors hold
(POSITION, NORMAL, TEXCOORD_0, COLOR_0, indices, the EXT_mesh_gpu_instancing attributes,
images) and by mesh name (the largest first): each accessor's bytes (in views that
several accessors share) counted once, by the first that reads it; views no accessor
reads (images) whole.

    scripts/gltf_breakdown.py city.glb [--meshes N]
"""
import argparse
import collections
import json
import struct
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("glb")
    ap.add_argument("--meshes", type=int, default=10, help="how many meshes to list (default 10)")
    args = ap.parse_args()
    data = open(args.glb, "rb").read()
    if data[:4] != b"glTF":
        sys.exit(f"{args.glb}: not a .glb")
    json_length = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + json_length])
    total = len(data)
    views = doc.get("bufferViews", [])
    counted, counted_views = set(), set()
    components = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
    widths = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
    by_kind = collections.Counter()
    by_mesh = collections.Counter()
    meshes_of_kind = collections.defaultdict(set)

    accessors = doc.get("accessors", [])

    def take(a, kind, owner):
        if a is None or a in counted or accessors[a].get("bufferView") is None:
            return
        counted.add(a)
        counted_views.add(accessors[a]["bufferView"])
        element = components[accessors[a]["componentType"]] * widths[accessors[a]["type"]]
        stride = views[accessors[a]["bufferView"]].get("byteStride", element)
        n = (accessors[a]["count"] - 1) * stride + element
        by_kind[kind] += n
        if owner is not None:
            by_mesh[owner] += n
            meshes_of_kind[kind].add(owner)

    def take_view(view, kind):
        if view is not None and view not in counted_views:
            counted_views.add(view)
            by_kind[kind] += views[view]["byteLength"]

    for mesh in doc.get("meshes", []):
        for p in mesh["primitives"]:
            for name, a in p["attributes"].items():
                take(a, name, mesh.get("name", "?"))
            if "indices" in p:
                take(p["indices"], "indices", mesh.get("name", "?"))
    for node in doc.get("nodes", []):
        inst = node.get("extensions", {}).get("EXT_mesh_gpu_instancing")
        if inst:
            for name, a in inst["attributes"].items():
                take(a, "instancing", None)
    for image in doc.get("images", []):
        take_view(image.get("bufferView"), "images")
    for v in range(len(views)):
        take_view(v, "other")

    print(f"{args.glb}: {total} bytes; JSON {json_length} ({100 * json_length / total:.1f} %), "
          f"{len(doc.get('meshes', []))} meshes, {len(doc.get('nodes', []))} nodes, {len(accessors)} accessors")
    for kind, n in by_kind.most_common():
        print(f"  {kind:12s} {n:10d}  {100 * n / total:5.1f} %")
    print(f"largest meshes (of {len(by_mesh)} names):")
    for name, n in by_mesh.most_common(args.meshes):
        print(f"  {name:30s} {n:10d}  {100 * n / total:5.1f} %")


if __name__ == "__main__":
    main()

"""Run inside Blender (issue #45, Blender as the client of fgsg's output):

  blender -b --factory-startup --python tests/cli/blender_check.py -- SCENE.glb GROUPED.obj LOTS.geojson [QUANTIZED.glb]

Imports the glTF scene with Blender's own importer and checks what Blender made of it
against the file's JSON, read here independently: an object per start shape named after
its lot's feature id; a shared mesh placed by a node per instance (--instancing nodes)
imported as that many objects sharing one mesh datablock; the file's materials with
their base colours and images; and glTF's +Y up turned into Blender's +Z up (the world
bounds of every mesh object equal the file's, axes swapped). Then the grouped OBJ: an
object per start shape (`o`) and its .mtl's materials with their Kd colours. Given
QUANTIZED.glb (the same run with --quantize: KHR_mesh_quantization), Blender imports it
too and every vertex of every lot lies within 1 mm of the float scene's in Blender.
Prints what it checked; exits 1 on the first mismatch."""
import collections
import json
import math
import struct
import sys

import bpy
import mathutils
import mathutils.kdtree


def fail(message):
    print("FAIL: " + message, flush=True)
    sys.exit(1)


def load_gltf_json(path):
    data = open(path, "rb").read()
    if data[:4] != b"glTF":
        fail(f"{path} is not a .glb")
    (json_len,) = struct.unpack_from("<I", data, 12)
    return json.loads(data[20:20 + json_len])


def world_bounds(objects):
    lo = mathutils.Vector((math.inf,) * 3)
    hi = mathutils.Vector((-math.inf,) * 3)
    for o in objects:
        if o.type != "MESH" or not o.data.vertices:
            continue
        for corner in o.bound_box:
            w = o.matrix_world @ mathutils.Vector(corner)
            lo = mathutils.Vector(map(min, lo, w))
            hi = mathutils.Vector(map(max, hi, w))
    return lo, hi


def gltf_bounds(doc):
    """World bounds of the file's meshes through its node tree, from accessor min/max
    (each mesh's POSITION bounds, corners transformed)."""
    nodes = doc["nodes"]
    lo = [math.inf] * 3
    hi = [-math.inf] * 3

    def local(node):
        if "matrix" in node:
            m = node["matrix"]
            return mathutils.Matrix([m[0:4], m[4:8], m[8:12], m[12:16]]).transposed()
        t = mathutils.Matrix.Translation(node.get("translation", [0, 0, 0]))
        x, y, z, w = node.get("rotation", [0, 0, 0, 1])
        r = mathutils.Quaternion((w, x, y, z)).to_matrix().to_4x4()
        sx, sy, sz = node.get("scale", [1, 1, 1])
        s = mathutils.Matrix.Diagonal((sx, sy, sz, 1))
        return t @ r @ s

    stack = [(i, mathutils.Matrix.Identity(4)) for i in doc["scenes"][0]["nodes"]]
    while stack:
        i, parent = stack.pop()
        node = nodes[i]
        world = parent @ local(node)
        if "mesh" in node:
            for p in doc["meshes"][node["mesh"]]["primitives"]:
                a = doc["accessors"][p["attributes"]["POSITION"]]
                for cx in (a["min"][0], a["max"][0]):
                    for cy in (a["min"][1], a["max"][1]):
                        for cz in (a["min"][2], a["max"][2]):
                            w = world @ mathutils.Vector((cx, cy, cz))
                            lo = [min(lo[d], w[d]) for d in range(3)]
                            hi = [max(hi[d], w[d]) for d in range(3)]
        stack.extend((c, world) for c in node.get("children", []))
    return lo, hi


def check_gltf(path, lots_path):
    doc = load_gltf_json(path)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    # Debian bookworm's Blender 3.4.1 fails with its numpy 1.24 when guessing flat faces
    # from normals (the default import_shading="NORMALS" uses the removed np.bool): smooth
    # shading, flat where a primitive has no normals, takes another path.
    bpy.ops.import_scene.gltf(filepath=path, import_shading="SMOOTH")
    objects = list(bpy.context.scene.objects)

    # A root object per start shape, named after its lot.
    features = json.load(open(lots_path))["features"]
    names = [str(f.get("id", f"feature {k}")) for k, f in enumerate(features)]
    roots = [o.name for o in objects if o.parent is None]
    missing = [n for n in names if n not in roots]
    if missing:
        fail(f"{len(missing)} lots have no root object in Blender, e.g. {missing[:3]} (roots: {roots[:5]}...)")
    print(f"roots: {len(roots)} objects without a parent, one per lot ({len(names)} lots)")
    # Its lot's properties as custom properties (glTF extras).
    for f in features[:5]:
        o = bpy.data.objects[str(f["id"])]
        for key, value in f.get("properties", {}).items():
            if isinstance(value, str) and o.get("properties", {}).get(key) != value:
                fail(f"object {o.name}: custom property properties.{key} is {o.get('properties', {}).get(key)!r}, not {value!r}")

    # Instances: the file's nodes placing a shared mesh, and Blender's objects sharing it.
    expected = collections.Counter()
    for n in doc["nodes"]:
        if "mesh" in n and "asset" in n.get("extras", {}):
            expected[doc["meshes"][n["mesh"]]["name"]] += 1
    if not expected:
        fail("the file places no shared mesh by a node per instance (write it with --instancing nodes)")
    # Per glTF mesh name (Blender numbers repeated names: "Wall piece.003"), the objects
    # placing it and the mesh datablocks they share.
    users = collections.Counter()
    datablocks = collections.defaultdict(set)
    for o in objects:
        if o.type == "MESH" and "asset" in o.keys():
            base, _, number = o.data.name.rpartition(".")
            name = base if base and number.isdigit() else o.data.name
            users[name] += 1
            datablocks[name].add(o.data.name)
    for name, count in sorted(expected.items()):
        if users[name] != count:
            fail(f"mesh {name!r}: {count} instance nodes in the file, {users[name]} objects in Blender")
        print(f"instances of {name!r}: {count} objects sharing {len(datablocks[name])} mesh datablock(s)")
    total_shared = sum(expected.values())
    total_blocks = sum(len(v) for v in datablocks.values())
    if total_blocks >= total_shared:
        fail(f"{total_shared} instances use {total_blocks} mesh datablocks: Blender did not share them")

    # Materials: each of the file's by name, with its base colour and image.
    for m in doc.get("materials", []):
        bm = bpy.data.materials.get(m["name"])
        if bm is None:
            fail(f"material {m['name']!r} is not in Blender ({[x.name for x in bpy.data.materials][:8]})")
        bsdf = next((n for n in bm.node_tree.nodes if n.type == "BSDF_PRINCIPLED"), None)
        if bsdf is None:
            fail(f"material {m['name']!r} has no Principled BSDF")
        pbr = m["pbrMetallicRoughness"]
        factor = pbr.get("baseColorFactor", [1, 1, 1, 1])
        base = bsdf.inputs["Base Color"]
        if "baseColorTexture" in pbr:
            images = [n for n in bm.node_tree.nodes if n.type == "TEX_IMAGE" and n.image is not None]
            if not images:
                fail(f"material {m['name']!r} has a baseColorTexture, Blender no image")
        elif not base.is_linked:
            got = list(base.default_value)[:3]
            if max(abs(a - b) for a, b in zip(got, factor[:3])) > 1e-4:
                fail(f"material {m['name']!r}: base colour {got} in Blender, {factor[:3]} in the file")
        if abs(bsdf.inputs["Roughness"].default_value - pbr.get("roughnessFactor", 1)) > 1e-4:
            fail(f"material {m['name']!r}: roughness {bsdf.inputs['Roughness'].default_value} in Blender")
    print(f"materials: {len(doc.get('materials', []))} in the file, found with their colours and images")

    # Up axis: glTF's (x, y, z) is Blender's (x, -z, y).
    flo, fhi = gltf_bounds(doc)
    want_lo = (flo[0], -fhi[2], flo[1])
    want_hi = (fhi[0], -flo[2], fhi[1])
    lo, hi = world_bounds(objects)
    diff = max(max(abs(a - b) for a, b in zip(lo, want_lo)), max(abs(a - b) for a, b in zip(hi, want_hi)))
    if diff > 1e-3:
        fail(f"world bounds in Blender {tuple(lo)}..{tuple(hi)}, expected {want_lo}..{want_hi} (glTF +Y up as Blender +Z)")
    print(f"up axis: Blender's bounds {tuple(round(x, 3) for x in lo)}..{tuple(round(x, 3) for x in hi)} "
          f"are the file's with +Y up turned to +Z (within {diff:.2g})")


def check_obj(path, lots_path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.wm.obj_import(filepath=path)
    objects = list(bpy.context.scene.objects)
    features = json.load(open(lots_path))["features"]
    names = {str(f.get("id", f"feature {k}")) for k, f in enumerate(features)}
    got = {o.name for o in objects}
    if not names <= got:
        fail(f"OBJ: {len(names - got)} lots have no object, e.g. {sorted(names - got)[:3]}")
    # Each newmtl of the .mtl with its Kd.
    mtl = path[:-4] + ".mtl"
    current = None
    materials = {}
    for line in open(mtl):
        words = line.split()
        if words[:1] == ["newmtl"]:
            current = words[1]
        elif words[:1] == ["Kd"]:
            materials[current] = [float(x) for x in words[1:4]]
    for name, kd in materials.items():
        bm = bpy.data.materials.get(name)
        if bm is None:
            fail(f"OBJ: material {name!r} of the .mtl is not in Blender")
        bsdf = next((n for n in bm.node_tree.nodes if n.type == "BSDF_PRINCIPLED"), None)
        got = list(bsdf.inputs["Base Color"].default_value)[:3]
        if not bsdf.inputs["Base Color"].is_linked and max(abs(a - b) for a, b in zip(got, kd)) > 1e-4:
            fail(f"OBJ: material {name!r}: base colour {got}, Kd {kd}")
    print(f"OBJ: an object per lot ({len(names)}), {len(materials)} materials of the .mtl with their Kd")


def imported_vertices(path):
    """Per root object (a lot), the world positions of the vertices of the mesh objects
    under it, as Blender imports the glTF file."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=path, import_shading="SMOOTH")
    out = collections.defaultdict(list)
    for o in bpy.context.scene.objects:
        if o.type != "MESH":
            continue
        root = o
        while root.parent is not None:
            root = root.parent
        out[root.name].extend(o.matrix_world @ v.co for v in o.data.vertices)
    return out


def check_quantized(float_path, quantized_path, tolerance=1e-3):
    want = imported_vertices(float_path)
    got = imported_vertices(quantized_path)
    if sorted(want) != sorted(got):
        fail(f"quantized: other root objects ({sorted(set(want) ^ set(got))[:3]})")
    worst, count = 0.0, 0
    for root, points in want.items():
        if len(points) != len(got[root]):
            fail(f"quantized: {root} has {len(got[root])} vertices in Blender, the float scene {len(points)}")
        tree = mathutils.kdtree.KDTree(len(points))
        for k, p in enumerate(points):
            tree.insert(p, k)
        tree.balance()
        for p in got[root]:
            worst = max(worst, tree.find(p)[2])
        count += len(points)
    if not worst <= tolerance:
        fail(f"quantized: a vertex is {worst} m from the float scene's nearest (> {tolerance})")
    print(f"quantized: {count} vertices of {len(want)} lots within {worst * 1000:.3f} mm of the float scene's "
          f"(tolerance {tolerance * 1000:.0f} mm)")


argv = sys.argv[sys.argv.index("--") + 1:]
check_gltf(argv[0], argv[2])
check_obj(argv[1], argv[2])
if len(argv) > 3:
    check_quantized(argv[0], argv[3])
print("blender ok", flush=True)

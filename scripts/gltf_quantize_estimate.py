#!/usr/bin/env python3
"""An estimate, not an output path: re-encodes a scene .glb (fgsg run's default) with
KHR_mesh_quantization to measure what it would save (issue #45's 1/10 target): baked
meshes' positions as UNSIGNED_SHORT on a uniform grid of their box (a child node scales
them back; the worst error is printed), every TEXCOORD_0 as SHORT in 1/1024-tile steps
(KHR_texture_transform on the textured materials), instance ROTATION as normalized SHORT.
Needs numpy. The result passes scripts/validate-gltf.js with 0 errors and 0 warnings.

    scripts/gltf_quantize_estimate.py city.glb city_quantized.glb
"""
import json, struct, sys
import numpy as np

src, dst = sys.argv[1:3]
d = open(src, 'rb').read()
n = struct.unpack_from('<I', d, 12)[0]
doc = json.loads(d[20:20 + n])
binc = d[28 + n:] if False else d[20 + n + 8:]
views, acc = doc['bufferViews'], doc['accessors']
CT = {5126: ('<f4', 4), 5123: ('<u2', 2), 5125: ('<u4', 4), 5122: ('<i2', 2), 5121: ('u1', 1)}
NC = {'SCALAR': 1, 'VEC2': 2, 'VEC3': 3, 'VEC4': 4}

def read(a):
    v = views[a['bufferView']]
    dt, size = CT[a['componentType']]
    k = NC[a['type']]
    off = v.get('byteOffset', 0) + a.get('byteOffset', 0)
    return np.frombuffer(binc, dtype=dt, count=a['count'] * k, offset=off).reshape(a['count'], k)

newviews, out = [], bytearray()
def put(arr, target=None):
    global out
    while len(out) % 4: out.append(0)
    v = {'buffer': 0, 'byteOffset': len(out), 'byteLength': arr.nbytes}
    if target: v['target'] = target
    out += arr.tobytes()
    newviews.append(v)
    return len(newviews) - 1

new_acc = {}
arrays = {}  # accessor -> (numpy array, componentType, normalized, target)
for i, a in enumerate(acc):
    if 'bufferView' in a:
        arrays[i] = read(a)

# Which accessors are what.
baked_nodes = [k for k, nd in enumerate(doc['nodes']) if 'mesh' in nd and 'asset' not in nd.get('extras', {})
               and 'EXT_mesh_gpu_instancing' not in nd.get('extensions', {})]
uv = set(); rot = set(); pos_of_mesh = {}
for m in doc['meshes']:
    for p in m['primitives']:
        if 'TEXCOORD_0' in p['attributes']: uv.add(p['attributes']['TEXCOORD_0'])
for nd in doc['nodes']:
    e = nd.get('extensions', {}).get('EXT_mesh_gpu_instancing')
    if e:
        rot.add(e['attributes']['ROTATION'])
        for name, a in e['attributes'].items():  # the others each in a view of its own, as they are
            if name != 'ROTATION':
                new_acc[a] = (np.ascontiguousarray(arrays[a]), acc[a]['componentType'], False, None, None, None)
for k in baked_nodes:
    nd = doc['nodes'][k]
    mesh = doc['meshes'][nd['mesh']]
    ps = sorted({p['attributes']['POSITION'] for p in mesh['primitives']})
    lo = np.min([arrays[a].min(0) for a in ps], 0).astype(np.float64)
    hi = np.max([arrays[a].max(0) for a in ps], 0).astype(np.float64)
    step = max((hi - lo).max() / 65535, 1e-9)
    worst = 0
    for a in ps:
        q = np.round((arrays[a] - lo) / step).astype(np.uint16)
        worst = max(worst, np.abs(q * step + lo - arrays[a]).max())
        q4 = np.zeros((len(q), 4), np.uint16); q4[:, :3] = q
        new_acc[a] = (q4, 5123, False, 34962, q.min(0).tolist(), q.max(0).tolist())
    child = {'name': nd['name'] + ' mesh', 'mesh': nd.pop('mesh'), 'translation': lo.tolist(), 'scale': [step] * 3}
    doc['nodes'].append(child)
    nd.setdefault('children', []).append(len(doc['nodes']) - 1)
    pos_of_mesh[k] = worst
STEP = 1024
for a in uv:
    t = arrays[a].astype(np.float64) * STEP
    assert np.abs(t).max() < 32767, np.abs(t).max()
    q = np.round(t).astype(np.int16)
    new_acc[a] = (q, 5122, False, 34962, None, None)
for a in rot:
    q = np.round(arrays[a].astype(np.float64) * 32767).astype(np.int16)
    new_acc[a] = (q, 5122, True, None, None, None)
for m in doc['materials']:
    t = m['pbrMetallicRoughness'].get('baseColorTexture')
    if t: t['extensions'] = {'KHR_texture_transform': {'scale': [1 / STEP, 1 / STEP]}}

# Rewrite: every accessor gets its own view (as packed), shared index views kept shared.
seen_view = {}
for i, a in enumerate(acc):
    if 'bufferView' not in a: continue
    if i in new_acc:
        q, ct, norm, target, mn, mx = new_acc[i]
        a['bufferView'] = put(q, target); a.pop('byteOffset', None)
        a['componentType'] = ct
        if norm: a['normalized'] = True
        if mn is not None: a['min'], a['max'] = mn, mx
        elif 'min' in a and ct != 5126: a.pop('min'); a.pop('max')
        if ct != 5126 and a['type'] == 'VEC3' and q.shape[1] == 4:
            newviews[-1]['byteStride'] = 8
    else:
        old = a['bufferView']
        if old not in seen_view:
            v = views[old]
            seen_view[old] = put(np.frombuffer(binc, 'u1', v['byteLength'], v.get('byteOffset', 0)).copy(), v.get('target'))
            if 'byteStride' in v: newviews[-1]['byteStride'] = v['byteStride']
        a['bufferView'] = seen_view[old]
for img in doc.get('images', []):
    v = views[img['bufferView']]
    img['bufferView'] = put(np.frombuffer(binc, 'u1', v['byteLength'], v.get('byteOffset', 0)).copy())
while len(out) % 4: out.append(0)
doc['bufferViews'] = newviews
doc['buffers'] = [{'byteLength': len(out)}]
doc['extensionsUsed'] = sorted(set(doc.get('extensionsUsed', []) + ['KHR_mesh_quantization', 'KHR_texture_transform']))
doc['extensionsRequired'] = ['KHR_mesh_quantization']
text = json.dumps(doc, separators=(',', ':')).encode()
text += b' ' * ((4 - len(text) % 4) % 4)
res = b'glTF' + struct.pack('<II', 2, 12 + 8 + len(text) + 8 + len(out)) + struct.pack('<I', len(text)) + b'JSON' + text + struct.pack('<I', len(out)) + b'BIN\0' + bytes(out)
open(dst, 'wb').write(res)
print(f'{len(d)} -> {len(res)} bytes; worst position error {max(pos_of_mesh.values())*1000:.3f} mm')

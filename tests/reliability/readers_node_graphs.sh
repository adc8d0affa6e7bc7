#!/usr/bin/env bash
# glTF and COLLADA files whose node graph or counts would make assimp expand without bound
# end at once with a located message, as surfaces (both engines) and as synthesis
# examples. The
# 2 KB file whose 40 nodes each list the next one twice as a child grew to 24 GB before
# the kernel killed fgsg; every run here is under a 4 GB address-space limit, so a
# regression fails this test instead of the machine.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
skip_under_asan "its refusals run under ulimit -v"
grammar="$inputs/readers_surface_grammar.fgsg"
# Runs "$fgsg" ARGS... under the limit: "${limited[@]}" ARGS...
limited=(bash -c 'ulimit -v 4000000 && exec "$0" "$@"' "$fgsg")

# A one-triangle mesh as glTF JSON with the given nodes and scenes (and extra accessors).
gltf() {  # FILE NODES SCENES [ACCESSOR_EXTRA]
  cat >"$1" <<JSON
{"asset": {"version": "2.0"},
 "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
               {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}${4:-}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
 "nodes": $2, "scenes": $3, "scene": 0}
JSON
}

check() {  # FILE REGEX: exit 1 with "FILE: REGEX", within seconds, for both engines and synth
  local file=$1 name message=$2 pattern start ms
  name=$(basename "$file" | sed 's/\./\\./g')
  pattern="$name: $message"
  for engine in interp jit; do
    start=$(date +%s%N)
    expect 1 "$pattern" -- "${limited[@]}" run "$grammar" --surface "$file" --engine=$engine -o "$tmp/x.obj"
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    [ "$ms" -lt 10000 ] || fail "$(basename "$file"): took $ms ms to refuse"
    grep -q 'error\[R015\]' "$tmp/err" || { cat "$tmp/err" >&2; fail "$(basename "$file"): not R015"; }
    same_message "${limited[@]}" run "$grammar" --surface "$file" --engine=$engine -o "$tmp/x.obj"
  done
  expect 1 "$name: error\[E750\]: $message" -- "${limited[@]}" synth "$file" --size 4 4 4 -o "$tmp/s.obj"
  [ ! -e "$tmp/x.obj" ] && [ ! -e "$tmp/s.obj" ] || fail "$(basename "$file"): an output was written"
}

# The reproducers: each node lists the next twice (2^40 and 2^20 copies).
check "$inputs/readers_g1_gltf_node_dag.gltf" \
  'nodes\[0\]\.children\[1\]: node 1 is listed twice among the children of node 0 \(glTF nodes form trees'
check "$inputs/readers_g1_gltf_node_dag20.gltf" \
  'nodes\[0\]\.children\[1\]: node 1 is listed twice among the children'

# The same as binary glTF (the JSON chunk of a .glb).
python3 - "$inputs/readers_g1_gltf_node_dag.gltf" "$tmp/dag.glb" <<'PY'
import struct, sys
text = open(sys.argv[1], 'rb').read().rstrip()
text += b' ' * (-len(text) % 4)
open(sys.argv[2], 'wb').write(b'glTF' + struct.pack('<II', 2, 20 + len(text)) + struct.pack('<I', len(text)) + b'JSON' + text)
PY
check "$tmp/dag.glb" 'nodes\[0\]\.children\[1\]: node 1 is listed twice among the children of node 0'

# A node with two parents, a cycle, a missing child, a scene listing a child or a node twice.
gltf "$tmp/two_parents.gltf" '[{"children": [2]}, {"children": [2]}, {"mesh": 0}]' '[{"nodes": [0, 1]}]'
check "$tmp/two_parents.gltf" 'nodes\[1\]\.children\[0\]: node 2 is already a child of node 0'
gltf "$tmp/cycle.gltf" '[{"mesh": 0}, {"children": [2]}, {"children": [1]}]' '[{"nodes": [0]}]'
check "$tmp/cycle.gltf" 'nodes\[[12]\]: node [12] is its own ancestor \(the node hierarchy has a cycle\)'
gltf "$tmp/missing.gltf" '[{"children": [7], "mesh": 0}]' '[{"nodes": [0]}]'
check "$tmp/missing.gltf" 'nodes\[0\]\.children\[0\]: names no node 7 \(there are 1\)'
gltf "$tmp/scene_child.gltf" '[{"children": [1]}, {"mesh": 0}]' '[{"nodes": [0, 1]}]'
check "$tmp/scene_child.gltf" 'scenes\[0\]\.nodes\[1\]: node 1 is a child of node 0, not a root'
gltf "$tmp/scene_twice.gltf" '[{"mesh": 0}]' '[{"nodes": [0, 0]}]'
check "$tmp/scene_twice.gltf" 'scenes\[0\]\.nodes\[1\]: node 0 is listed twice'

# Counts: an accessor beyond its view; one without a view (zeros made in memory) of 2^31
# elements; a buffer larger than any input file.
gltf "$tmp/accessor.gltf" '[{"mesh": 0}]' '[{"nodes": [0]}]' \
  ', {"bufferView": 0, "componentType": 5126, "count": 1000000000, "type": "VEC3"}'
check "$tmp/accessor.gltf" 'accessors\[2\]: 1000000000 elements of 12 bytes need 12000000000 bytes of buffer view 0, which has 36'
gltf "$tmp/zeros.gltf" '[{"mesh": 0}]' '[{"nodes": [0]}]' \
  ', {"componentType": 5126, "count": 2147483647, "type": "MAT4"}'
check "$tmp/zeros.gltf" 'reading it would take about .*, more than the memory limit of .* \(--max-memory\)'
sed 's/"byteLength": 44,/"byteLength": 4000000000,/' "$tmp/zeros.gltf" >"$tmp/big_buffer.gltf"
check "$tmp/big_buffer.gltf" 'buffers\[0\]: byteLength 4000000000 is larger than an input file may be'

# Instancing within the rules: 20 000 nodes placing one 2 000 000-triangle mesh (its
# indices declared by an accessor without a view) are refused by the triangle bound
# before anything is read.
nodes=$(python3 -c 'print("[" + ", ".join(["{\"mesh\": 0}"] * 20000) + "]")')
roots=$(python3 -c 'print("[{\"nodes\": [" + ", ".join(str(i) for i in range(20000)) + "]}]")')
gltf "$tmp/instances.gltf" "$nodes" "$roots"
sed -i 's/{"bufferView": 1, "componentType": 5123, "count": 3,/{"componentType": 5123, "count": 6000000,/' "$tmp/instances.gltf"
check "$tmp/instances.gltf" 'its 20000 nodes place 40000000000 triangles, more than a surface may have \(67108864\)'

# --max-memory bounds the reader too: 1 000 instances of a 60 000-triangle mesh (60 M
# triangles, within the triangle bound) are refused under a 1G memory limit.
nodes=$(python3 -c 'print("[" + ", ".join(["{\"mesh\": 0}"] * 1000) + "]")')
roots=$(python3 -c 'print("[{\"nodes\": [" + ", ".join(str(i) for i in range(1000)) + "]}]")')
gltf "$tmp/budget.gltf" "$nodes" "$roots"
sed -i 's/{"bufferView": 1, "componentType": 5123, "count": 3,/{"componentType": 5123, "count": 180000,/' "$tmp/budget.gltf"
expect 1 'budget\.gltf: reading it would take about .*, more than the memory limit of 1G \(--max-memory\)' -- \
  "${limited[@]}" run "$grammar" --surface "$tmp/budget.gltf" --max-memory 1G -o "$tmp/x.obj"

# COLLADA: 30 nodes, each instancing the next twice (<instance_node>: a copy each), and a
# node instancing its own ancestor.
python3 - "$tmp" <<'PY'
import sys
N = 30
tri = ('<library_geometries><geometry id="tri"><mesh><source id="p">'
       '<float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array><technique_common>'
       '<accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>'
       '<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common>'
       '</source><vertices id="v"><input semantic="POSITION" source="#p"/></vertices>'
       '<triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p>'
       '</triangles></mesh></geometry></library_geometries>\n')
def doc(nodes):
    return ('<?xml version="1.0" encoding="utf-8"?>\n<COLLADA xmlns="http://www.collada.org/2005/11/'
            'COLLADASchema" version="1.4.1">\n<asset><up_axis>Z_UP</up_axis></asset>\n' + tri +
            '<library_nodes>\n' + nodes + '</library_nodes>\n<library_visual_scenes><visual_scene id="s">'
            '<node id="root"><instance_node url="#n0"/></node></visual_scene></library_visual_scenes>\n'
            '<scene><instance_visual_scene url="#s"/></scene>\n</COLLADA>\n')
dag = ''.join('<node id="n%d"><instance_geometry url="#tri"/>%s</node>\n' % (
    i, '<instance_node url="#n%d"/>' % (i + 1) * 2 if i + 1 < N else '') for i in range(N))
open(sys.argv[1] + '/dag.dae', 'w').write(doc(dag))
cycle = ('<node id="n0"><instance_geometry url="#tri"/><node id="n1">'
         '<instance_node url="#n0"/></node></node>\n')
open(sys.argv[1] + '/cycle.dae', 'w').write(doc(cycle))
PY
for engine in interp jit; do
  expect 1 "dag\.dae:[0-9]+: node 'n[0-9]+' expands to [0-9]+ nodes through <instance_node> \(each instance is a copy\), more than 1048576" -- \
    "${limited[@]}" run "$grammar" --surface "$tmp/dag.dae" --engine=$engine -o "$tmp/x.obj"
  expect 1 "cycle\.dae:[0-9]+: node 'n0' contains itself through <instance_node> \(the node graph has a cycle\)" -- \
    "${limited[@]}" run "$grammar" --surface "$tmp/cycle.dae" --engine=$engine -o "$tmp/x.obj"
done

# The same hierarchy as a tree (each node's child listed once) is a valid surface.
gltf "$tmp/tree.gltf" '[{"children": [1], "mesh": 0}, {"mesh": 0, "translation": [2, 0, 0]}]' '[{"nodes": [0]}]'
timeout 60 "${limited[@]}" run "$grammar" --surface "$tmp/tree.gltf" -q -o "$tmp/x.obj" 2>"$tmp/err" ||
  { cat "$tmp/err" >&2; fail "a valid glTF tree was refused"; }
exit 0

#!/usr/bin/env bash
# FBX files whose model connections would make assimp expand without bound end at once
# with a located message (runtime/io/check_fbx.h), as surfaces, both engines. assimp builds
# a node for every connection of a model to a parent: 20 models each connected twice to
# the next became 2^19 nodes (4.5 GB, 44 s; 26 models would exhaust any machine), and a
# cycle of connections crashed fgsg (assimp recursed until the stack overflowed). Every
# run here is under a 4 GB address-space limit, so a regression fails this test instead of
# the machine. The files are ASCII FBX 7.4 and binary FBX 7400, written here.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
skip_under_asan "its refusals run under ulimit -v"
grammar="$inputs/readers_surface_grammar.fgsg"
limited=(bash -c 'ulimit -v 4000000 && exec "$0" "$@"' "$fgsg")

# fbx MODELS COPIES FILE [cycle|binary]...: a tetrahedron below a chain of models, each
# connected COPIES times to the one before it (the first to the root).
fbx() {
  python3 - "$@" <<'PY'
import struct, sys
n, dup, path, flags = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], sys.argv[4:]
links = [(200, 0)] + [(200 + k, 199 + k) for k in range(1, n) for _ in range(dup)]
if "cycle" in flags:
    links.append((200, 200 + n - 1))
links.append((100, 200 + n - 1))
if "binary" not in flags:
    o = ["; FBX 7.4.0 project file", "FBXHeaderExtension:  {", "\tFBXHeaderVersion: 1003", "\tFBXVersion: 7400", "}",
         "Objects:  {", '\tGeometry: 100, "Geometry::tetra", "Mesh" {',
         "\t\tVertices: *12 {", "\t\t\ta: 0,0,0,1,0,0,0,1,0,0,0,1", "\t\t}",
         "\t\tPolygonVertexIndex: *12 {", "\t\t\ta: 0,2,-2,0,1,-4,0,3,-3,1,2,-4", "\t\t}", "\t}"]
    for k in range(n):
        o += ['\tModel: %d, "Model::m%d", "%s" {' % (200 + k, k, "Mesh" if k == n - 1 else "Null"), "\t\tVersion: 232", "\t}"]
    o += ["}", "Connections:  {"] + ['\tC: "OO",%d,%d' % l for l in links] + ["}"]
    open(path, "w").write("\n".join(o) + "\n")
    sys.exit(0)
def prop(t, v):
    if t == "I": return b"I" + struct.pack("<i", v)
    if t == "L": return b"L" + struct.pack("<q", v)
    if t == "S": return b"S" + struct.pack("<I", len(v)) + v.encode("latin1")
    data = b"".join(struct.pack("<d" if t == "d" else "<i", x) for x in v)
    return t.encode() + struct.pack("<III", len(v), 0, len(data)) + data
def record(name, props, children=()):
    def at(pos):
        pb = b"".join(prop(*p) for p in props)
        head = 13 + len(name) + len(pb)
        body, p = b"", pos + head
        for c in children:
            b = c(p)
            body, p = body + b, p + len(b)
        if children:
            body += b"\0" * 13
        return struct.pack("<IIIB", pos + head + len(body), len(props), len(pb), len(name)) + name.encode() + pb + body
    return at
objects = [record("Geometry", [("L", 100), ("S", "tetra\0\1Geometry"), ("S", "Mesh")],
                  [record("Vertices", [("d", [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1])]),
                   record("PolygonVertexIndex", [("i", [0, 2, -2, 0, 1, -4, 0, 3, -3, 1, 2, -4])]),
                   record("GeometryVersion", [("I", 124)])])]
objects += [record("Model", [("L", 200 + k), ("S", "m%d\0\1Model" % k), ("S", "Mesh" if k == n - 1 else "Null")],
                   [record("Version", [("I", 232)])]) for k in range(n)]
top = [record("FBXHeaderExtension", [], [record("FBXVersion", [("I", 7400)])]), record("Objects", [], objects),
       record("Connections", [], [record("C", [("S", "OO"), ("L", c), ("L", p)]) for c, p in links])]
out = b"Kaydara FBX Binary  \0\x1a\0" + struct.pack("<I", 7400)
for r in top:
    out += r(len(out))
open(path, "wb").write(out + b"\0" * 13)
PY
}

refused() {  # FILE REGEX: exit 1 with "FILE...: REGEX" (R015), within seconds, both engines
  local file=$1 pattern start ms
  pattern="$(basename "$file" | sed 's/\./\\./g')$2"
  for engine in interp jit; do
    start=$(date +%s%N)
    expect 1 "$pattern" -- "${limited[@]}" run "$grammar" --surface "$file" --engine=$engine -o "$tmp/x.obj"
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    [ "$ms" -lt 10000 ] || fail "$(basename "$file"): took $ms ms to refuse"
    grep -q 'error\[R015\]' "$tmp/err" || { cat "$tmp/err" >&2; fail "$(basename "$file"): not R015"; }
    same_message "${limited[@]}" run "$grammar" --surface "$file" --engine=$engine -o "$tmp/x.obj"
  done
  [ ! -e "$tmp/x.obj" ] || fail "$(basename "$file"): an output was written"
}

# Sound files read: the tetrahedron once, and below a chain of 12 models connected once.
for flags in "" binary; do
  fbx 1 1 "$tmp/tetra$flags.fbx" $flags
  fbx 12 1 "$tmp/chain$flags.fbx" $flags
  for f in "$tmp/tetra$flags.fbx" "$tmp/chain$flags.fbx"; do
    timeout 60 "${limited[@]}" run "$grammar" --surface "$f" -o "$tmp/ok.obj" 2>"$tmp/err" ||
      { cat "$tmp/err" >&2; fail "$(basename "$f") does not read"; }
  done
done

# The reproducer: 26 models each connected twice to the one before (2^25 copies), and 21
# (2^20, just past the bound), ASCII and binary.
fbx 26 2 "$tmp/twice26.fbx"
refused "$tmp/twice26.fbx" ':[0-9]+: .*the models. connections expand to more than 1048576 nodes \(here model 2[0-9]+ \(.m[0-9]+.\) is placed once more'
fbx 21 2 "$tmp/twice21.fbx"
refused "$tmp/twice21.fbx" ':[0-9]+: .*expand to more than 1048576 nodes'
fbx 26 2 "$tmp/twice26b.fbx" binary
refused "$tmp/twice26b.fbx" ': byte [0-9]+: .*expand to more than 1048576 nodes'

# Within the node bound, but not within --max-memory (2^18 nodes, about 1 GB).
fbx 18 2 "$tmp/twice18.fbx"
for engine in interp jit; do
  expect 1 'twice18\.fbx: its models. connections expand to 262143 nodes, about [0-9.]+[MG] to read, more than the memory limit of 256M \(--max-memory\)' -- \
    "${limited[@]}" run "$grammar" --surface "$tmp/twice18.fbx" --max-memory 256M --engine=$engine -o "$tmp/x.obj"
done

# A cycle of connections (was a crash), ASCII and binary, and a chain deeper than 1024.
fbx 3 1 "$tmp/cycle.fbx" cycle
refused "$tmp/cycle.fbx" ":[0-9]+: model 200 \\('m0'\\) is connected below itself \\(a cycle of connections\\)"
fbx 3 1 "$tmp/cycleb.fbx" cycle binary
refused "$tmp/cycleb.fbx" ": byte [0-9]+: model 200 \\('m0'\\) is connected below itself"
fbx 1100 1 "$tmp/deep.fbx"
refused "$tmp/deep.fbx" ":[0-9]+: model 1224 \\('m1024'\\) is nested deeper than 1024 levels of models"
exit 0

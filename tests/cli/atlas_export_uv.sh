#!/usr/bin/env bash
# fgsg atlas --export-uv (#49): the OBJ reads back with the mesh's faces and UVs in [0,1];
# an image painted through those UVs, written as plain PGM (P2) by this script, keeps a
# march out of the painted faces, exactly as the same image as binary PGM (P5) does;
# bad names and folders are refused with no file left, a broken P2 with its line.
#   atlas_export_uv.sh FGSG SOURCE_DIR
set -u
fgsg="$1" source="$2"
fail=0
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
export FGSG_CACHE_DIR="$work/cache"
mesh="$source/tests/data/meshes/sphere.ply"  # radius 0.5, 320 faces

out="$("$fgsg" atlas "$mesh" --resolution 256 --export-uv sphere_uv.obj 2>&1)" \
  || { echo "FAIL: fgsg atlas --export-uv exited $?: $out"; exit 1; }
grep -qF "wrote sphere_uv.obj (320 faces" <<<"$out" || { echo "FAIL: no 'wrote' line: $out"; fail=1; }

# Read the OBJ; paint, through its UVs, the faces whose centroid has x > 0.1 white on a
# 128 x 128 image (row 0 is v = 1); write it as P2 (comments, ragged blanks) and as P5.
python3 - <<'PY' || fail=1
import sys
v, vt, faces = [], [], []
for line in open("sphere_uv.obj"):
    w = line.split()
    if not w or w[0].startswith("#"): continue
    if w[0] == "v": v.append(tuple(map(float, w[1:4])))
    elif w[0] == "vt": vt.append(tuple(map(float, w[1:3])))
    elif w[0] == "f": faces.append([tuple(int(i) - 1 for i in c.split("/")) for c in w[1:]])
    else: sys.exit("FAIL: unexpected OBJ line: " + line)
ok = len(faces) == 320 and len(v) == 162 and len(vt) > len(v)
ok = ok and all(len(f) == 3 for f in faces) and all(0 <= a <= 1 and 0 <= b <= 1 for a, b in vt)
if not ok: sys.exit("FAIL: %d faces, %d v, %d vt, or UVs outside [0,1]" % (len(faces), len(v), len(vt)))
n = 128
img = [[0] * n for _ in range(n)]
def inside(p, a, b, c):
    d = lambda p, q, r: (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
    s = (d(a, b, p), d(b, c, p), d(c, a, p))
    return all(x >= 0 for x in s) or all(x <= 0 for x in s)
white = 0
for f in faces:
    if sum(v[i][0] for i, _ in f) / 3 <= 0.1: continue
    white += 1
    tri = [(vt[t][0] * n, vt[t][1] * n) for _, t in f]
    for y in range(n):
        for x in range(n):
            if inside((x + 0.5, y + 0.5), *tri): img[n - 1 - y][x] = 255
if white < 50: sys.exit("FAIL: only %d faces painted" % white)
# Grow the painted texels into their neighbours (as fgsg's own masks do) so bilinear
# lookups at a chart's edge read the chart.
for _ in range(2):
    grown = [row[:] for row in img]
    for y in range(n):
        for x in range(n):
            if any(img[j][i] for j in range(max(0, y - 1), min(n, y + 2)) for i in range(max(0, x - 1), min(n, x + 2))):
                grown[y][x] = 255
    img = grown
with open("paint_p2.pgm", "w") as out:
    out.write("P2\n# painted through sphere_uv.obj\n%d  %d\n255\n" % (n, n))
    for row in img: out.write(" \t".join(map(str, row)) + "\n")
with open("paint_p5.pgm", "wb") as out:
    out.write(b"P5 %d %d 255\n" % (n, n) + bytes(b for row in img for b in row))
with open("black.pgm", "w") as out:
    out.write("P2 %d %d 1\n" % (n, n) + "0 " * (n * n))
PY

march() {  # MASK OUT: march from (-0.5, 0, 0) up over the top towards +X while the mask reads dark
  sed "s/MASK/$1/" >"$1.fgsg" <<'G'
surface sphere(1);
texture paint = "MASK";
start = Walk(0)
Walk(n) : n < 80 ~> Marching(0.03, Rand(-2, 2), context.paint(texCoord) < 0.5){ I("cube") Walk(n + 1) }
G
  # The run lays the mesh out at the resolution the OBJ was exported at: the same atlas.
  "$fgsg" run "$1.fgsg" --surface "$mesh" --atlas-resolution 256 --seed-points -0.5,0,0:0,1,0 -o "$2" -q \
    --instances "$2.json" >"$2.log" 2>&1 || { echo "FAIL: fgsg run with $1 exited $?:"; cat "$2.log"; fail=1; }
}
farthest() {  # INSTANCES.json: the largest x an instance was placed at
  python3 -c 'import json, sys; print(max(i["transform"][12] for i in json.load(open(sys.argv[1]))["instances"]))' "$1"
}
placed() {  # INSTANCES.json: how many instances
  python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["instances"]))' "$1"
}
march paint_p2.pgm p2.obj
march paint_p5.pgm p5.obj
march black.pgm black.obj
cmp -s p2.obj p5.obj || { echo "FAIL: the P2 and P5 masks give different models"; fail=1; }
cmp -s p2.obj.json p5.obj.json || { echo "FAIL: the P2 and P5 masks give different instances"; fail=1; }
# Unpainted, the march crosses over to the +X side; painted, it keeps out of the faces
# painted through the OBJ's UVs (centroid x > 0.1).
python3 -c 'import sys; sys.exit(not float(sys.argv[1]) > 0.3)' "$(farthest black.obj.json)" \
  || { echo "FAIL: the unpainted march stops at x = $(farthest black.obj.json)"; fail=1; }
python3 -c 'import sys; sys.exit(not float(sys.argv[1]) < 0.1)' "$(farthest p2.obj.json)" \
  || { echo "FAIL: the march enters the painted faces, at x = $(farthest p2.obj.json)"; fail=1; }
# ... going around them for its 80 steps: a mask painted in the wrong place would stop it
# at the seed or let it in.
[ "$(placed p2.obj.json)" -eq 81 ] && [ "$(placed black.obj.json)" -eq 81 ] \
  || { echo "FAIL: $(placed p2.obj.json) and $(placed black.obj.json) instances, not 81 each"; fail=1; }

# Bad names and folders.
expect() {  # CODE TEXT ARGS...
  local code="$1" line="$2" out rc
  shift 2
  out="$("$fgsg" "$@" 2>&1 </dev/null)"
  rc=$?
  if [ "$rc" -ne "$code" ] || ! grep -qF -- "$line" <<<"$out"; then
    echo "FAIL: fgsg $* exited $rc (expected $code), printing:"; echo "$out"; echo "expected: $line"; fail=1
  fi
}
expect 2 "--export-uv uv.ply: the mesh with its texture coordinates is an OBJ file (name it .obj)" \
  atlas "$mesh" --export-uv uv.ply
expect 1 "cannot write 'missing/uv.obj'" atlas "$mesh" --resolution 256 --export-uv missing/uv.obj
[ ! -e missing ] || { echo "FAIL: a folder was made"; fail=1; }
# A broken plain mask names the file and the line.
printf 'P2\n2 1\n255\n1\nx\n' >bad.pgm
sed "s/paint_p2.pgm/bad.pgm/" paint_p2.pgm.fgsg >bad.fgsg
expect 1 "bad.pgm: the plain PGM/PPM file has 'x' at line 5 in sample 2 (row 1, column 2)" \
  run bad.fgsg --surface "$mesh" --atlas-resolution 256 --seed-points -0.5,0,0 -o bad.obj
exit $fail

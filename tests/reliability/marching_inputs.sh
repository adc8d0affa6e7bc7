#!/usr/bin/env bash
# On-mesh marching's inputs, as a user meets them: seed lists and flags, textures that
# cannot be read, meshes whose texture coordinates cannot be an atlas, a damaged atlas
# cache. Each ends in a clear message and the documented exit code, never a crash.
. "$(dirname "$0")/lib.sh"
export FGSG_CACHE_DIR="$tmp/cache"
cd "$tmp" || fail "no scratch folder"

cat > walk.fgsg <<'G'
surface sphere(1);
texture paint = "paint.png";
start = Walk(0)
Walk(n) : n < 5 ~> Marching(0.1, 0, context.paint(texCoord) > 0.5){ I("cube") Walk(n + 1) }
G
cp "$root/examples/assets/ivy_anywhere.png" paint.png

# Flags.
expect 2 "seed-points: 'x,1,2' is not a seed" -- "$fgsg" run walk.fgsg --seed-points "x,1,2"
expect 2 "seed-points: '1,2' is not a seed" -- "$fgsg" run walk.fgsg --seed-points "0,0,1;1,2"
printf '0 0 1\n0 0 1 0 0 0\n' > zero_heading.txt
expect 2 "zero_heading.txt:2: expected a seed" -- "$fgsg" run walk.fgsg --seed-points zero_heading.txt
expect 2 "no_seeds.txt: .*(no such file|not found|cannot)" -- "$fgsg" run walk.fgsg --seed-points no_seeds.txt
expect 2 "march-units fathoms" -- "$fgsg" run walk.fgsg --march-units fathoms
expect 2 "march-candidates" -- "$fgsg" run walk.fgsg --march-candidates 65
expect 2 "atlas-resolution" -- "$fgsg" run walk.fgsg --atlas-resolution 8
echo 'start = I("cube")' > plane.fgsg
expect 2 "seed-points needs a surface" -- "$fgsg" run plane.fgsg --seed-points "0,0,1"
"$fgsg" run walk.fgsg -q -o ok.glb --seed-points "0,0,1;1,0,0:0,1,0" || fail "two seeds did not run"
[ -s ok.glb ] || fail "no output for two seeds"

# Textures that cannot be read: at the declaration, nothing written.
rm -f out.glb
printf 'not a picture' > paint.png
expect 1 "walk.fgsg:2:1: error\[R023\].*paint.png" -- "$fgsg" run walk.fgsg -o out.glb
[ -e out.glb ] && fail "an output was written for an unreadable texture"
head -c 40 "$root/examples/assets/ivy_anywhere.png" > paint.png  # a truncated PNG
expect 1 "error\[R023\].*paint.png" -- "$fgsg" run walk.fgsg -o out.glb
rm paint.png
expect 1 "error\[R023\].*paint.png" -- "$fgsg" run walk.fgsg -o out.glb
# A valid PNG 20000 texels wide, past the documented 16384 per side: refused by its size.
python3 - <<'P'
import struct, zlib
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
w, h = 20000, 2
raw = b''.join(b'\0' + b'\xff' * w for _ in range(h))
open('paint.png', 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 0, 0, 0, 0))
                             + chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))
P
expect 1 "error\[R023\].*paint.png.*(large|size)" -- "$fgsg" run walk.fgsg -o out.glb

# A mesh whose texture coordinates overlap cannot be an atlas: located by face.
cat > overlap.obj <<'M'
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
f 1/1 2/2 3/3
f 1/1 3/2 4/4
M
expect 1 "overlap.*face" -- "$fgsg" atlas overlap.obj
cp "$root/examples/assets/ivy_anywhere.png" paint.png
expect 1 "error\[R023\].*overlap" -- "$fgsg" run walk.fgsg --surface overlap.obj -o out.glb

# fgsg atlas: flags, and a damaged cache is rebuilt, never trusted.
expect 2 "no mesh given" -- "$fgsg" atlas
expect 2 "paint expects a sphere" -- "$fgsg" atlas "$root/tests/data/meshes/elephant.off" --paint 1,2,3 --mask m.png
expect 2 "paint-slab need --mask" -- "$fgsg" atlas "$root/tests/data/meshes/elephant.off" --paint 1,2,3,4
expect 2 "previews are PNG" -- "$fgsg" atlas "$root/tests/data/meshes/elephant.off" --preview atlas.jpg
"$fgsg" atlas "$root/tests/data/meshes/elephant.off" --resolution 256 > first.txt || fail "fgsg atlas failed"
grep -q "built" first.txt || fail "the first atlas was not built: $(cat first.txt)"
"$fgsg" atlas "$root/tests/data/meshes/elephant.off" --resolution 256 > second.txt || fail "fgsg atlas failed"
grep -q "read from the cache" second.txt || fail "the second atlas did not come from the cache: $(cat second.txt)"
for f in "$FGSG_CACHE_DIR"/atlas/*; do head -c 100 "$f" > "$f.cut" && mv "$f.cut" "$f"; done
"$fgsg" atlas "$root/tests/data/meshes/elephant.off" --resolution 256 > third.txt || fail "a damaged cache broke fgsg atlas"
grep -q "built" third.txt || fail "a damaged cache was trusted: $(cat third.txt)"
echo "ok: $test_name"

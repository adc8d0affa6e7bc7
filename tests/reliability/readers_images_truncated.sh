#!/usr/bin/env bash
# Images are read by one reader that tells formats by their first bytes and refuses a
# truncated file: a 28-byte cut-off TGA named .png read as an image field gave a
# different output on every run (stb_image's TGA decoder left the pixels uninitialised);
# cut-off PNG and BMP files were decoded as if zeros followed; Texture() embedded a
# cut-off PNG in the .glb. Each is now one located error, the same on every run.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
succeeds() { timeout 60 "$@" >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "'$*' failed"; }; }
cd "$tmp" || fail "no scratch folder"

# The reproducer: an image field reading the TGA, both engines, and as a synthesis example.
for engine in interp jit; do
  expect 1 'error\[R015\]: .*readers_i1_tga_trunc\.png: not an image fgsg reads \(PNG, JPEG, BMP, PGM/PPM\)' -- \
    "$fgsg" run "$inputs/readers_i1_image_field_tga.fgsg" --engine=$engine -o "$tmp/f.obj"
  same_message "$fgsg" run "$inputs/readers_i1_image_field_tga.fgsg" --engine=$engine -o "$tmp/f.obj"
done
expect 1 'readers_i1_tga_trunc\.png.*not an image fgsg reads' -- \
  "$fgsg" synth "$inputs/readers_i1_tga_trunc.png" --size 8 8 1 --labels "$tmp/l.txt"
[ ! -e f.obj ] && [ ! -e l.txt ] || fail "an output was written from the TGA"

# A PNG and a BMP, whole and cut off (written here: no image library needed).
python3 - <<'PY'
import struct, zlib
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
w = h = 16
raw = b''.join(b'\0' + bytes(((x * 16 + y) & 255) for x in range(w) for _ in range(3)) for y in range(h))
png = (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) +
       chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))
open('good.png', 'wb').write(png)
open('cut.png', 'wb').write(png[:len(png) - 30])   # inside the pixel data
open('noend.png', 'wb').write(png[:len(png) - 12])  # every pixel, no IEND
pix = bytes([10, 20, 30] * 16) * 16
bmp = (b'BM' + struct.pack('<IHHI', 54 + len(pix), 0, 0, 54) +
       struct.pack('<IiiHHIIiiII', 40, 16, 16, 1, 24, 0, len(pix), 0, 0, 0, 0) + pix)
open('good.bmp', 'wb').write(bmp)
open('cut.bmp', 'wb').write(bmp[:len(bmp) - 100])
PY
field() {  # IMAGE: a grammar reading IMAGE as an image field
  sed "s/readers_i1_tga_trunc\.png/$1/" "$inputs/readers_i1_image_field_tga.fgsg" >"field_$1.fgsg"
  echo "field_$1.fgsg"
}
for engine in interp jit; do
  expect 1 "cut\.png: the PNG file is truncated: its 'IDAT' chunk at byte 33 declares" -- \
    "$fgsg" run "$(field cut.png)" --engine=$engine -o out.obj
  expect 1 'noend\.png: the PNG file is truncated: it ends after [0-9]+ bytes, before its IEND chunk' -- \
    "$fgsg" run "$(field noend.png)" --engine=$engine -o out.obj
  expect 1 'cut\.bmp: the BMP file is truncated: its header declares 822 bytes of header and pixels, the file has 722' -- \
    "$fgsg" run "$(field cut.bmp)" --engine=$engine -o out.obj
  # Whole files read, the same way on every run.
  for good in good.png good.bmp; do
    succeeds "$fgsg" run "$(field $good)" --engine=$engine -q -o a.obj
    succeeds "$fgsg" run "$(field $good)" --engine=$engine -q -o b.obj
    cmp -s a.obj b.obj || fail "$good: two runs wrote different outputs"
  done
done

# Texture() refuses a cut-off PNG before deriving: it would be embedded in the .glb as it is.
printf 'axiom: Lot;\nLot ~> S(4, 3, 2) Texture("%s") Subdiv("X", 1r){ Mass };\n' cut.png >texture_cut.fgsg
printf 'axiom: Lot;\nLot ~> S(4, 3, 2) Texture("%s") Subdiv("X", 1r){ Mass };\n' good.png >texture_good.fgsg
for engine in interp jit; do
  expect 1 "error\[R003\]: Texture: .*cut\.png: the PNG file is truncated" -- \
    "$fgsg" run texture_cut.fgsg --engine=$engine -o t.glb
  [ ! -e t.glb ] || fail "a .glb was written with a cut-off texture"
  succeeds "$fgsg" run texture_good.fgsg --engine=$engine -q -o t.glb
  grep -qa 'image/png' t.glb || fail "the whole PNG was not embedded"
  rm -f t.glb
done
exit 0

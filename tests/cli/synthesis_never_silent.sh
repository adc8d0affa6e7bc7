#!/usr/bin/env bash
# `fgsg synth` never writes a silent empty file (#46): a continuous model with no solid is
# E752 naming why (a --fixed-width wider than the box), a discrete model that is empty
# space everywhere is E746; --closed with --mask works (the mask's outside is exempt from
# the closed faces), and nothing is written when the run fails.
. "$(dirname "$0")/../reliability/lib.sh"
cd "$root" || fail "no source folder"

# Continuous: objects 3 plane spacings tall in a box 2 high cannot exist.
expect 1 'error\[E752\]: the synthesized model is empty \(0 parts\), nothing was written: --fixed-width 0,1,0:3 makes every object 3 plane spacings across along \(0,1,0\), but the box spans only 2 of them that way \(it is the box.s height, --size.s Z\)' -- \
  "$fgsg" synth examples/synthesis/continuous/box.obj --size 10 10 2 --fixed-width 0,1,0:3 -o "$tmp/low.glb"
[ -e "$tmp/low.glb" ] && fail "E752 wrote low.glb"
# The same width in a box 5 high makes parts.
expect 0 'wrote .*tall.glb \([1-9][0-9]* parts' -- \
  "$fgsg" synth examples/synthesis/continuous/box.obj --size 10 10 5 --fixed-width 0,1,0:3 -o "$tmp/tall.glb"

# Discrete: a mask white all over leaves only the empty label.
cat >"$tmp/one.txt" <<'TXT'
label . none empty
label A cube
size 3 3 2
layer 0
. . .
. A .
. . .
layer 1
. . .
. . .
. . .
TXT
printf 'P6\n1 1\n255\n\377\377\377' >"$tmp/white.ppm"
expect 1 'error\[E746\]: the synthesized model is empty space in every cell \(label \.\), nothing was written: the constraints allow nothing but empty space here; try ' -- \
  "$fgsg" synth "$tmp/one.txt" --size 8 8 2 --mask "$tmp/white.ppm" -o "$tmp/none.glb" --labels "$tmp/none.txt"
[ -e "$tmp/none.glb" ] || [ -e "$tmp/none.txt" ] && fail "E746 wrote a file"

# --closed with --mask: was E740 (cell (0,0,0) could hold no label); now a model.
expect 0 'wrote .*f.txt' -- \
  "$fgsg" synth examples/synthesis/city.txt --size 40 40 5 --block 10 --closed \
  --mask examples/synthesis/letter_f.png --labels "$tmp/f.txt"
exit 0

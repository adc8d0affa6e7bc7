#!/usr/bin/env bash
# Paints the texture masks of the on-mesh marching examples (Buron et al. Fig. 10) with
# `fgsg atlas --paint`: each mask lives in the texture coordinates of its mesh's
# generated atlas, so a change to the atlas builder must repaint them. The test
# "reliability: marching_masks" repaints into a scratch folder and compares.
#   scripts/paint-example-masks.sh FGSG [OUT_DIR]   (default OUT_DIR: examples/assets)
set -euo pipefail
fgsg=${1:?fgsg binary}
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out=${2:-$root/examples/assets}
meshes="$root/tests/data/meshes"
# Fig. 10b: forbidden areas on the bunny — its back and its head.
"$fgsg" atlas "$meshes/bunny00.off" --surface-size 2 --mask-size 512 \
  --paint 0.1,0.35,-0.1,0.45 --paint -0.55,0.45,0.2,0.25 --mask "$out/fig10b_bunny_forbidden.png" >/dev/null
# Fig. 10c: a painted path on the elephant — two strokes around its body.
"$fgsg" atlas "$meshes/elephant.off" --surface-size 2 --mask-size 512 \
  --paint-slab 0,0,0,0,1,0,0.07 --paint-slab 0,0,0,1,0,0,0.07 --mask "$out/fig10c_elephant_path.png" >/dev/null

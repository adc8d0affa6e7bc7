#!/usr/bin/env bash
# One command from a fresh Debian bookworm machine to a first result: installs what
# building and running need (not the test tools), builds fgsg with its plugins (not the
# tests, not the Python package: setup-and-test.sh builds everything) and runs the main
# example: stems and leaves growing along a designed field over the embedded torus (FGSG
# Fig. 13), writing out/stem_leaf.glb and the preview out/stem_leaf.png.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" fgsg
mkdir -p "$root/out"
# --instancing nodes: a node per leaf, which Debian's Blender (3.4) imports; the default
# EXT_mesh_gpu_instancing scene is smaller but that Blender reads each leaf mesh once.
"$root/build/bin/fgsg" run "$root/examples/stem_leaf.fgsg" --instancing nodes \
  -o "$root/out/stem_leaf.glb" --preview "$root/out/stem_leaf.png" --stats
echo "fgsg: open out/stem_leaf.glb in Blender (File > Import > glTF 2.0); preview in out/stem_leaf.png"

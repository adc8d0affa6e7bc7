#!/usr/bin/env bash
# One command from a fresh Debian bookworm machine to a first result: installs what is
# missing, builds (Release) and runs the main example, writing out/building.glb and the
# preview out/building.png.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
mkdir -p "$root/out"
"$root/build/bin/fgsg" run "$root/examples/mueller_building.fgsg" \
  -o "$root/out/building.glb" --preview "$root/out/building.png" --stats
echo "fgsg: open out/building.glb in Blender (File > Import > glTF 2.0); preview in out/building.png"

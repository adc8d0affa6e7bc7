#!/usr/bin/env bash
# Configures and builds fgsg (Release) into build/. Used by the set-up scripts.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j "$jobs"
# `import fgsg` in python3 without PYTHONPATH: the build's package on the user's site path
# (docs/python.md; a later build of another checkout takes its place).
if site="$(python3 -m site --user-site 2>/dev/null)" && mkdir -p "$site" 2>/dev/null; then
  echo "$root/build/python" > "$site/fgsg-build.pth"
fi

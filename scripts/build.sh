#!/usr/bin/env bash
# Configures and builds fgsg (Release) into build/. Used by the set-up scripts.
#   build.sh            everything: fgsg, its plugins, the Python package, the tests
#   build.sh TARGET...  only those targets (setup-and-run.sh: fgsg, which brings its
#                       plugins, libfgsg.so and the viewer's page)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jobs=$(nproc 2>/dev/null || echo 2)
# A new build directory compiles fgsg's libraries in batches (FGSG_UNITY_BUILD, #47: half
# the processor time of a cold build); an existing one keeps its choice, and
# FGSG_UNITY_BUILD=ON or OFF in the environment sets it.
unity=()
if [ -n "${FGSG_UNITY_BUILD:-}" ]; then
  unity=(-DFGSG_UNITY_BUILD="$FGSG_UNITY_BUILD")
elif [ ! -f "$root/build/CMakeCache.txt" ]; then
  unity=(-DFGSG_UNITY_BUILD=ON)
fi
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${unity[@]}" >/dev/null
if [ $# -gt 0 ]; then
  cmake --build "$root/build" -j "$jobs" --target "$@"
else
  cmake --build "$root/build" -j "$jobs"
fi
# `import fgsg` in python3 without PYTHONPATH: the build's package on the user's site path
# (docs/python.md; a later build of another checkout takes its place). Only once built.
if compgen -G "$root/build/python/fgsg/_fgsg*.so" >/dev/null &&
   site="$(python3 -m site --user-site 2>/dev/null)" && mkdir -p "$site" 2>/dev/null; then
  echo "$root/build/python" > "$site/fgsg-build.pth"
fi

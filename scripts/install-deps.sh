#!/usr/bin/env bash
# Installs the Debian bookworm packages fgsg builds against. Idempotent and non-interactive:
# packages already present are skipped, so a second run costs one dpkg query.
# Without arguments: what building fgsg and running it needs (setup-and-run.sh).
# --test: also what the Python package and the tests need (setup-and-test.sh passes it):
# numpy and dask, pytest, chromium and Blender, the npm packages (three.js for fgsg
# view's page, the glTF validator, playwright-core) and CGAL's test meshes.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# pybind11-dev and python3-dev: CMake configures the Python package even when only fgsg
# is built. catch2: CMake finds it at configure time too (header-only, small).
packages=(
  build-essential cmake ninja-build pkg-config
  libantlr4-runtime-dev
  llvm-19-dev
  libeigen3-dev libopenmesh-dev
  catch2
  libtbb-dev libfcl-dev libembree-dev
  libtinygltf-dev libstb-dev libedit-dev libfmt-dev
  nlohmann-json3-dev
  libcgal-dev libgmp-dev libmpfr-dev libassimp-dev libnanoflann-dev
  zlib1g-dev libzstd-dev libxml2-dev libffi-dev libncurses-dev
  libwebsocketpp-dev libboost-dev libcli11-dev
  python3-dev pybind11-dev
)

# Only for the Python package and the tests. venv, setuptools and wheel: `pip install .`
# offline (tests/python/pip_install.sh); chromium: the viewer's browser tests; Blender
# imports fgsg's glTF and OBJ output headless (tests/cli/blender_import.sh; about 106 MB
# to download, 3 minutes to install).
# antlr4 (the tool, with a Java runtime): only to regenerate the parsers checked in under
# grammar/generated (scripts/regen-grammar.sh); building needs only its C++ runtime.
# time: /usr/bin/time measures the peak memory under --max-memory
# (tests/reliability/limits_memory.sh).
test_packages=(python3-numpy python3-pytest python3-distributed python3-venv python3-setuptools python3-wheel
               chromium blender antlr4 time)
testing=false
[ "${1:-}" = "--test" ] && testing=true
$testing && packages+=("${test_packages[@]}")

missing=()
# Node.js may come from another source (it bundles npm); only ask Debian when absent.
$testing && { command -v npm >/dev/null 2>&1 || missing+=(nodejs npm); }
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "fgsg: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null
fi

if $testing; then
  # npm packages: the official glTF validator judges the .glb files the tests write;
  # three.js draws fgsg view's page, playwright-core drives chromium in its tests.
  "$here/install-node-packages.sh"
  # Real-world test meshes from CGAL's data (tests/data/README.md); offline once fetched.
  "$here/fetch-test-meshes.sh"
fi

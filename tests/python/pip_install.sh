#!/usr/bin/env bash
# `pip install .` and `pip wheel .` (pyproject.toml, setup.py) offline with Debian's tools,
# as docs/python.md says: into a fresh venv (--system-site-packages: numpy from Debian),
# the installed package derives a grammar with its own JIT plugin, whatever the build's
# package or FGSG_LIBDIR say. usage: pip_install.sh PYTHON SOURCE_DIR BINARY_DIR
set -u
python="$1" source="$2" build="$3"
fail=0
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
version="$(sed -n 's/^project(fgsg VERSION \([0-9.]*\).*/\1/p' "$source/CMakeLists.txt")"
tag="$("$python" -c 'import sys; print(f"cp{sys.version_info[0]}{sys.version_info[1]}")')"

"$python" -m venv --system-site-packages "$work/venv" || { echo "FAIL: python3 -m venv"; exit 1; }
pip=("$work/venv/bin/python" -m pip --disable-pip-version-check --no-input)
# --no-index: nothing may be downloaded; the build is the one CMake made (FGSG_BUILD_DIR).
if ! FGSG_BUILD_DIR="$build" "${pip[@]}" wheel --no-index --no-build-isolation --no-deps -w "$work/wheels" \
     "$source" >"$work/wheel.log" 2>&1; then
  echo "FAIL: pip wheel"; cat "$work/wheel.log"; exit 1
fi
wheel="$work/wheels/fgsg-$version-$tag-$tag-linux_x86_64.whl"
[ -f "$wheel" ] || { echo "FAIL: no $(basename "$wheel"):"; ls "$work/wheels"; exit 1; }
listing="$("$python" -m zipfile -l "$wheel")"
for f in fgsg/__init__.py fgsg/__init__.pyi fgsg/batch.py fgsg/py.typed "fgsg/_fgsg.cpython-${tag#cp}" \
         fgsg/lib/libfgsg_llvm.so "fgsg-$version.dist-info/LICENSE"; do
  grep -q "^$f" <<<"$(awk '{print $1}' <<<"$listing")" || { echo "FAIL: the wheel lacks $f"; fail=1; }
done

if ! FGSG_BUILD_DIR="$build" "${pip[@]}" install --no-index --no-build-isolation "$source" >"$work/install.log" 2>&1; then
  echo "FAIL: pip install ."; cat "$work/install.log"; exit 1
fi
# Not the build's package (-s: the set-up's user-site .pth points at build/python), not
# the build's plugins: the venv's own, from another folder.
cd "$work" || exit 1
env -u PYTHONPATH -u FGSG_LIBDIR FGSG_CACHE_DIR="$work/cache" "$work/venv/bin/python" -s - "$source" "$version" <<'PY' || fail=1
import os, sys
import fgsg
source, version = sys.argv[1], sys.argv[2]
here = os.path.dirname(fgsg.__file__)
assert here.startswith(sys.prefix + os.sep), f"FAIL: fgsg imported from {here}, not the venv {sys.prefix}"
assert fgsg.__version__ == version, f"FAIL: fgsg.__version__ is {fgsg.__version__!r}, not {version!r}"
assert os.environ["FGSG_LIBDIR"] == os.path.join(here, "lib"), f"FAIL: plugins from {os.environ['FGSG_LIBDIR']}"
g = fgsg.Grammar.from_file(os.path.join(source, "examples", "koch.fgsg"))
jit, interp = g.generate(seed=2), g.generate(seed=2, engine="interp")
assert jit.stats["triangles"] == 32768, f"FAIL: {jit.stats}"
assert (jit.positions == interp.positions).all(), "FAIL: the JIT and the interpreter differ"
PY
exit $fail

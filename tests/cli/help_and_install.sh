#!/usr/bin/env bash
# The CLI's conventions: every subcommand's --help prints its usage and exits 0; the
# install target lays out a prefix whose fgsg runs a grammar, compiles one to a library
# and finds its viewer page (usage: help_and_install.sh FGSG SOURCE_DIR BINARY_DIR).
set -u
fgsg="$1" source="$2" build="$3"
fail=0
for cmd in run check ir synth repl compile atlas evolve field view batch; do
  out="$("$fgsg" "$cmd" --help 2>&1 </dev/null)"
  code=$?
  if [ "$code" -ne 0 ] || ! grep -q "usage" <<<"$out" || ! grep -q "fgsg $cmd" <<<"$out"; then
    echo "FAIL: fgsg $cmd --help exited $code:"; echo "$out"; fail=1
  fi
done
"$fgsg" run -h </dev/null | grep -q -- "--max-seconds S" || { echo "FAIL: fgsg run -h lacks the option notes"; fail=1; }

prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT
if ! cmake --install "$build" --prefix "$prefix" >/dev/null; then
  echo "FAIL: cmake --install"; exit 1
fi
for f in bin/fgsg lib/libfgsg.so lib/libfgsg_llvm.so lib/libfgsg_fcl.so share/fgsg/viewer/index.html \
         share/fgsg/viewer/three/build/three.module.js share/fgsg/stdlib/cga/facade.fgsg share/fgsg/stdlib/README.md; do
  [ -e "$prefix/$f" ] || { echo "FAIL: $f not installed"; fail=1; }
done
cd "$prefix"
FGSG_CACHE_DIR="$prefix/cache" "$prefix/bin/fgsg" run "$source/examples/fig4_local_pattern.fgsg" -o "$prefix/fig4.glb" --quiet \
  || { echo "FAIL: the installed fgsg cannot run a grammar"; fail=1; }
[ -s "$prefix/fig4.glb" ] || { echo "FAIL: no fig4.glb"; fail=1; }
FGSG_CACHE_DIR="$prefix/cache" "$prefix/bin/fgsg" run "$source/examples/lock_flowers.fgsg" -o "$prefix/flowers.glb" --quiet \
  || { echo "FAIL: the installed fgsg cannot place collision-tested instances (FCL plugin)"; fail=1; }
# The installed standard library, found beside bin/ (a module only it has proves which one).
mkdir -p "$prefix/share/fgsg/stdlib/only_installed"
printf 'Mark ~> I("cube");\n' > "$prefix/share/fgsg/stdlib/only_installed/mark.fgsg"
printf 'import "std/only_installed/mark" as m;\naxiom: m.Mark;\n' > "$prefix/uses_installed.fgsg"
env -u FGSG_STDLIB FGSG_CACHE_DIR="$prefix/cache" "$prefix/bin/fgsg" run "$prefix/uses_installed.fgsg" -o "$prefix/m.glb" --quiet \
  || { echo "FAIL: the installed fgsg does not find its standard library"; fail=1; }
env -u FGSG_STDLIB FGSG_CACHE_DIR="$prefix/cache" "$prefix/bin/fgsg" run "$source/examples/stdlib_house.fgsg" -o "$prefix/house.glb" --quiet \
  || { echo "FAIL: the installed fgsg cannot build the house from its standard library"; fail=1; }
"$prefix/bin/fgsg" compile "$source/examples/koch.fgsg" -o "$prefix/libkoch.so" --quiet \
  || { echo "FAIL: the installed fgsg cannot compile a grammar library"; fail=1; }
# The installed Python package finds its engine's plugins in PREFIX/lib.
env -u FGSG_LIBDIR FGSG_CACHE_DIR="$prefix/cache" PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c "
import fgsg
r = fgsg.Grammar.from_file('$source/examples/koch.fgsg').generate(seed=2)
assert len(r.indices) > 0
" || { echo "FAIL: the installed Python package cannot derive a grammar"; fail=1; }
exit $fail

#!/usr/bin/env bash
# Ahead-of-time compilation end to end, as examples/c_api/README.md shows it: fgsg
# compile builds libstem_leaf.so and stem_leaf.h, examples/c_api/generate.c builds
# against them with cc and runs; its file must be fgsg run's, byte for byte. Then the
# generic driver tests/tools/run_library.c gives fgsg run's bytes with options.
#   usage: c_example.sh FGSG RUN_LIBRARY SOURCE_ROOT
set -uo pipefail
fgsg=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
run_library=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL [c_example]: $*" >&2; exit 1; }
cd "$root" || fail "no repository root $root"
libdir=$(cd "$(dirname "$fgsg")/../lib" && pwd -P) || fail "no lib/ folder beside $(dirname "$fgsg")"
cc=${CC:-cc}

# libfgsg.so exports the C API and every runtime entry point of runtime/abi.def, nothing
# else (no C++ of the static libraries), and does not pull in libLLVM.
nm -D --defined-only "$libdir/libfgsg.so" | awk '{ print $3 }' | sort >"$tmp/exports"
grep -v '^fgsg_' "$tmp/exports" | head -5 | grep . && fail "libfgsg.so exports more than fgsg_* symbols"
for fn in fgsg_generator_create fgsg_generate fgsg_write fgsg_last_error \
  $(grep -oE '^FGSG_RT_(FN|MATH)\(fgsg_rt_[a-z0-9_]+' runtime/abi.def | sed 's/.*(//'); do
  grep -qx "$fn" "$tmp/exports" || fail "libfgsg.so does not export $fn"
done
readelf -d "$libdir/libfgsg.so" | grep -q 'NEEDED.*LLVM' && fail "libfgsg.so needs libLLVM"

"$fgsg" compile examples/stem_leaf.fgsg -o "$tmp/libstem_leaf.so" >"$tmp/compile.out" 2>&1 ||
  { cat "$tmp/compile.out" >&2; fail "fgsg compile failed"; }
grep -qF "wrote $tmp/libstem_leaf.so and $tmp/stem_leaf.h" "$tmp/compile.out" ||
  { cat "$tmp/compile.out" >&2; fail "fgsg compile did not say what it wrote"; }
[ -s "$tmp/stem_leaf.h" ] || fail "no header stem_leaf.h"
ls -a "$tmp" | grep -q '\.tmp' && fail "a temporary file was left beside the library"
readelf -d "$tmp/libstem_leaf.so" | grep -q 'NEEDED.*\[libfgsg\.so\]' || fail "libstem_leaf.so does not need libfgsg.so"
readelf -d "$tmp/libstem_leaf.so" | grep -qF "$libdir" || fail "libstem_leaf.so has no run path to $libdir"
nm -D --defined-only "$tmp/libstem_leaf.so" | grep -qw fgsg_program_stem_leaf || fail "fgsg_program_stem_leaf is not exported"

# The example program, strictly compiled, as the README builds it.
"$cc" -std=c99 -Wall -Wextra -Werror -I"$tmp" examples/c_api/generate.c -o "$tmp/generate" \
  -L"$tmp" -L"$libdir" -lstem_leaf -lfgsg -Wl,-rpath,"$tmp" -Wl,-rpath,"$libdir" 2>"$tmp/cc.out" ||
  { cat "$tmp/cc.out" >&2; fail "examples/c_api/generate.c does not build"; }
# The header is C++ too, and may be included twice.
printf '#include "stem_leaf.h"\n#include "stem_leaf.h"\nint main() { fgsg_generator* g = stem_leaf_create(); fgsg_generator_free(g); }\n' |
  c++ -std=c++17 -Wall -Werror -fsyntax-only -I"$tmp" -x c++ - || fail "stem_leaf.h does not compile as C++"

(cd "$tmp" && ./generate 7 out.glb) >"$tmp/counts" 2>"$tmp/generate.err" ||
  { cat "$tmp/generate.err" >&2; fail "generate failed"; }
[ -s "$tmp/out.glb" ] || fail "generate wrote no out.glb"
vertices=$(awk '$1 == "vertices" { print $2 }' "$tmp/counts")
triangles=$(awk '$1 == "triangles" { print $2 }' "$tmp/counts")
instances=$(awk '$1 == "instances" { print $2 }' "$tmp/counts")
[ -n "$vertices" ] && [ "$vertices" -gt 0 ] || { cat "$tmp/counts" >&2; fail "no vertex count"; }
[ -n "$triangles" ] && [ "$triangles" -gt 0 ] || { cat "$tmp/counts" >&2; fail "no triangle count"; }
[ -n "$instances" ] && [ "$instances" -gt 0 ] || { cat "$tmp/counts" >&2; fail "no instance count"; }

"$fgsg" run examples/stem_leaf.fgsg --seed 7 -o "$tmp/ref.glb" --instancing off --group-by none 2>"$tmp/run.err" ||
  { cat "$tmp/run.err" >&2; fail "fgsg run failed"; }
cmp -s "$tmp/out.glb" "$tmp/ref.glb" || fail "generate's out.glb differs from fgsg run's"
grep -qF "($instances instances, $triangles triangles)" "$tmp/run.err" ||
  { cat "$tmp/counts" "$tmp/run.err" >&2; fail "the counts differ from fgsg run's"; }
(cd "$tmp" && ./generate 8 out8.glb >/dev/null 2>&1) || fail "generate failed with seed 8"
cmp -s "$tmp/out.glb" "$tmp/out8.glb" && fail "seeds 7 and 8 gave the same mesh"

# The generic driver with fgsg run's flags.
check_same() {
  local ext=$1
  shift
  # The library's C API writes the flattened mesh (fgsg run's .glb is a scene by default).
  "$fgsg" run examples/stem_leaf.fgsg "$@" -o "$tmp/cli.$ext" --quiet --instancing off --group-by none 2>"$tmp/run.err" ||
    { cat "$tmp/run.err" >&2; fail "fgsg run $*"; }
  "$run_library" "$tmp/libstem_leaf.so" "$@" -o "$tmp/lib.$ext" --quiet 2>"$tmp/lib.err" ||
    { cat "$tmp/lib.err" >&2; fail "run_library $*"; }
  cmp -s "$tmp/cli.$ext" "$tmp/lib.$ext" || fail "run_library $* differs from fgsg run"
}
check_same ply --seed 3 --max-shapes 4000
check_same obj --seed=9 --collide-all --max-depth 60
[ -f tests/data/meshes/bunny00.off ] ||
  fail "tests/data/meshes/bunny00.off is missing: run scripts/fetch-test-meshes.sh (the test set-up, scripts/install-deps.sh --test, does)"
check_same glb --seed 4 --surface tests/data/meshes/bunny00.off --surface-size 8 --start 0,1,0 --max-shapes 3000
"$run_library" "$tmp/libstem_leaf.so" --set nope=1 -o "$tmp/x.glb" 2>"$tmp/lib.err" && fail "run_library accepted --set nope=1"
grep -q 'R010' "$tmp/lib.err" || { cat "$tmp/lib.err" >&2; fail "no R010 for an unknown attribute"; }
[ -e "$tmp/x.glb" ] && fail "a file was written although generating failed"
echo "ok: c_example"

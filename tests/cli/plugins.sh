#!/usr/bin/env bash
# Heavy libraries are loaded only by the commands that use them (issue #18): the code
# generator and the JIT are a plugin, lib/libfgsg_llvm.so, opened on first need, and a
# run whose code is cached loads the cache's shared library with dlopen alone; FCL's
# collision tests are lib/libfgsg_fcl.so, opened when a grammar places its first
# obstacle. Checked by the libraries each process loads (LD_DEBUG=files); without a
# plugin or the C compiler fgsg says why and goes on where it can.
. "$(dirname "$0")/../reliability/lib.sh"
grammar="$root/examples/koch.fgsg"
export FGSG_CACHE_DIR="$tmp/cache"

# loads WHAT COMMAND...: COMMAND succeeds; its loaded libraries are in $tmp/libs.
loads() {
  local what=$1
  shift
  LD_DEBUG=files "$@" >"$tmp/out" 2>"$tmp/debug" || { grep -v "^ *[0-9]*:" "$tmp/debug" >&2; fail "$what failed"; }
  grep -o "file=[^ ]*" "$tmp/debug" | sort -u >"$tmp/libs"
}
no_llvm() { ! grep -qE "libLLVM|libfgsg_llvm" "$tmp/libs" || fail "$1 loaded LLVM: $(grep -E 'LLVM|llvm' "$tmp/libs" | tr '\n' ' ')"; }
no_fcl() { ! grep -qE "libfcl|libfgsg_fcl" "$tmp/libs" || fail "$1 loaded FCL"; }

loads "--version" "$fgsg" --version
no_llvm "--version"
no_fcl "--version"
loads "check" "$fgsg" check "$grammar"
no_llvm "check"
loads "ir" "$fgsg" ir "$grammar"
no_llvm "ir"
loads "synth" "$fgsg" synth "$root/examples/synthesis/castle.txt" --size 10 10 10 --labels "$tmp/labels.txt"
no_llvm "synth"
loads "run --engine=interp" "$fgsg" run "$grammar" --engine=interp -q -o "$tmp/interp.glb"
no_llvm "run --engine=interp"
no_fcl "a grammar without collisions"
flowers="$root/examples/lock_flowers.fgsg"
loads "a grammar with IC" "$fgsg" run "$flowers" --engine=interp -q -o "$tmp/flowers.glb"
grep -q "libfgsg_fcl.so" "$tmp/libs" || fail "a grammar with IC did not load the collision plugin"

# The first run compiles through the plugin and leaves the object and its library.
loads "the first run" "$fgsg" run "$grammar" -q --stats -o "$tmp/a.glb"
grep -q "libfgsg_llvm.so" "$tmp/libs" || fail "the first run did not load the plugin"
grep -qx "time.engine jit" "$tmp/out" || fail "the first run did not compile"
ls "$tmp"/cache/*.o >/dev/null 2>&1 || fail "no object in the cache"
ls "$tmp"/cache/*.so >/dev/null 2>&1 || fail "no library in the cache"
# The second loads the library alone.
loads "the cached run" "$fgsg" run "$grammar" -q --stats -o "$tmp/b.glb"
no_llvm "the cached run"
grep -qx "time.engine jit-cached" "$tmp/out" || fail "the second run did not use the cache"
cmp "$tmp/a.glb" "$tmp/b.glb" || fail "the cache's library gave other bytes"
cmp "$tmp/a.glb" "$tmp/interp.glb" || fail "JIT and interpreter differ"

# A damaged library is linked again from the cached object, still without LLVM.
for so in "$tmp"/cache/*.so; do echo "not a library" >"$so"; done
loads "a run with a damaged library" "$fgsg" run "$grammar" -q --stats -o "$tmp/c.glb"
no_llvm "a run with a damaged library"
grep -qx "time.engine jit-cached" "$tmp/out" || fail "the cache was not used"
cmp "$tmp/a.glb" "$tmp/c.glb" || fail "the library linked again gave other bytes"
loads "the run after the repair" "$fgsg" run "$grammar" -q -o "$tmp/c2.glb"
no_llvm "the run after the repair"

# Without a C compiler the cache keeps objects only, and runs load them through the JIT;
# once there is one, the library is linked from the object.
export FGSG_CACHE_DIR="$tmp/cache2"
FGSG_CC=/nonexistent/cc "$fgsg" run "$grammar" -q -o "$tmp/d.glb" || fail "FGSG_CC missing: run failed"
ls "$tmp"/cache2/*.o >/dev/null 2>&1 || fail "FGSG_CC missing: no object in the cache"
! ls "$tmp"/cache2/*.so >/dev/null 2>&1 || fail "FGSG_CC missing: a library in the cache"
loads "FGSG_CC missing: the second run" env FGSG_CC=/nonexistent/cc "$fgsg" run "$grammar" -q --stats -o "$tmp/e.glb"
grep -q "libfgsg_llvm.so" "$tmp/libs" || fail "FGSG_CC missing: the object was not loaded by the JIT"
grep -qx "time.engine jit-cached" "$tmp/out" || fail "FGSG_CC missing: the object was not used"
cmp "$tmp/a.glb" "$tmp/e.glb" || fail "FGSG_CC missing: other bytes"
loads "a C compiler again" "$fgsg" run "$grammar" -q -o "$tmp/e2.glb"
no_llvm "a C compiler again"
ls "$tmp"/cache2/*.so >/dev/null 2>&1 || fail "the library was not linked from the object"

# Without the plugin: the commands that compile say so and name the way around it.
mkdir -p "$tmp/nolib"
export FGSG_CACHE_DIR=off
expect 1 "error\[R900\]: the JIT cannot compile this grammar: libfgsg_llvm.so is not in .*nolib \(FGSG_LIBDIR\).*--engine=interp" -- \
  env FGSG_LIBDIR="$tmp/nolib" "$fgsg" run "$grammar" -o "$tmp/f.glb"
[ ! -e "$tmp/f.glb" ] || fail "a run that could not compile wrote output"
FGSG_LIBDIR="$tmp/nolib" "$fgsg" run "$grammar" --engine=interp -q -o "$tmp/g.glb" || fail "--engine=interp needs the plugin"
cmp "$tmp/a.glb" "$tmp/g.glb" || fail "--engine=interp without the plugin: other bytes"
expect 1 "fgsg ir: libfgsg_llvm.so is not in" -- env FGSG_LIBDIR="$tmp/nolib" "$fgsg" ir "$grammar" --llvm
expect 1 "error\[R900\]: this grammar needs a part of fgsg that cannot be loaded: libfgsg_fcl.so is not in" -- \
  env FGSG_LIBDIR="$tmp/nolib" "$fgsg" run "$flowers" --engine=interp -o "$tmp/h.glb"
[ ! -e "$tmp/h.glb" ] || fail "a run without the collision plugin wrote output"
echo "ok: plugins"

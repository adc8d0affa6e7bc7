#!/usr/bin/env bash
# fgsg run --engine, the JIT's object cache and fgsg ir --llvm as a user meets them: a bad engine name is
# a usage error (exit 2); a second run of a grammar takes its code from the cache; a
# cache that is off or cannot be written changes nothing in the output.
. "$(dirname "$0")/../reliability/lib.sh"
grammar="$root/examples/koch.fgsg"

"$fgsg" run "$grammar" --engine=fast -o "$tmp/x.glb" 2>"$tmp/err"
[ $? -eq 2 ] || fail "--engine=fast: expected exit code 2"
grep -q "unknown engine (use interp or jit)" "$tmp/err" || fail "no message for --engine=fast"
[ -f "$tmp/x.glb" ] && fail "a usage error wrote output"
echo x | "$fgsg" repl --engine=fast >/dev/null 2>&1
[ $? -eq 2 ] || fail "fgsg repl --engine=fast: expected exit code 2"

export FGSG_CACHE_DIR="$tmp/cache"
"$fgsg" run "$grammar" -q --stats -o "$tmp/a.glb" >"$tmp/s1" || fail "first run failed"
grep -qx "time.engine jit" "$tmp/s1" || fail "the first run did not compile: $(grep engine "$tmp/s1")"
"$fgsg" run "$grammar" -q --stats -o "$tmp/b.glb" >"$tmp/s2" || fail "second run failed"
grep -qx "time.engine jit-cached" "$tmp/s2" || fail "the second run did not use the cache"
ls "$tmp"/cache/*.o >/dev/null 2>&1 || fail "no object in the cache folder"
cmp "$tmp/a.glb" "$tmp/b.glb" || fail "cached code gave other bytes"

FGSG_CACHE_DIR=off "$fgsg" run "$grammar" -q --stats -o "$tmp/c.glb" >"$tmp/s3" || fail "run without cache failed"
grep -qx "time.engine jit" "$tmp/s3" || fail "FGSG_CACHE_DIR=off still read the cache"
cmp "$tmp/a.glb" "$tmp/c.glb" || fail "no cache: other bytes"

# A folder below a plain file cannot be made, not even by root.
FGSG_CACHE_DIR="$tmp/a.glb/cache" "$fgsg" run "$grammar" -q -o "$tmp/d.glb" 2>"$tmp/err4" \
  || { cat "$tmp/err4" >&2; fail "an unwritable cache folder made the run fail"; }
cmp "$tmp/a.glb" "$tmp/d.glb" || fail "unwritable cache: other bytes"

"$fgsg" run "$grammar" --engine interp -q -o "$tmp/e.glb" || fail "--engine interp failed"
cmp "$tmp/a.glb" "$tmp/e.glb" || fail "interpreter and JIT differ"
# fgsg ir --llvm shows what the JIT compiles: Fig. 4's symbols are derived directly.
"$fgsg" ir "$root/examples/fig4_local_pattern.fgsg" --llvm >"$tmp/ll" || fail "fgsg ir --llvm failed"
grep -q "^define internal void @fgsg_direct_A(" "$tmp/ll" || fail "no direct function for A in fgsg ir --llvm"
grep -q "^@fgsg_program = " "$tmp/ll" || fail "no program table in fgsg ir --llvm"
"$fgsg" ir --llvm >/dev/null 2>&1
[ $? -eq 2 ] || fail "fgsg ir --llvm without a file: expected exit code 2"
echo "ok: engine flag and object cache"

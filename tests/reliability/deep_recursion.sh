#!/usr/bin/env bash
# Deep recursion never overflows the native stack: the JIT's direct derivation stops
# recursing near the thread's stack floor and the engine derives in its own order (same
# bytes as the interpreter), and Lock sets continue on a stack of their own. Both hold
# on a small stack (ulimit -s) as on the default one.
. "$(dirname "$0")/lib.sh"

# (02 grows breadth-first: its 20 M default shapes take long on a loaded machine.)
for g in 01_jit_stack_overflow_chain 02_jit_stack_overflow_binary fuzz_w0_01142.min; do
  for engine in jit interp; do
    expect 0 "R004.*(depth limit|derivation stopped)" -- "$fgsg" run "$inputs/$g.fgsg" --engine=$engine \
      --max-shapes 1000000 -o "$tmp/$g.$engine.glb"
  done
  cmp -s "$tmp/$g.jit.glb" "$tmp/$g.interp.glb" || fail "$g: the engines wrote other bytes"
done

# 03 places instances: the engine puts them in its own order, whichever path ran.
for engine in jit interp; do
  expect 0 "R004.*200000 shapes" -- "$fgsg" run "$inputs/03_jit_stack_overflow_max_shapes.fgsg" \
    --max-shapes 200000 --engine=$engine -o "$tmp/03.$engine.glb"
done
cmp -s "$tmp/03.jit.glb" "$tmp/03.interp.glb" || fail "03: the engines wrote other bytes"

# A chain of 50 000 instances, inside the documented limits, on a 1 MiB stack.
cat >"$tmp/chain.fgsg" <<'G'
axiom: A(0);
A(k): k < 50000 ~> I("cube") T(1, 0, 0) A(k + 1);
G
for engine in jit interp; do
  ( ulimit -s 1024; exec "$fgsg" run "$tmp/chain.fgsg" --engine=$engine -q -o "$tmp/chain.$engine.glb" ) 2>"$tmp/err" \
    || { cat "$tmp/err" >&2; fail "chain of 50000 on a 1 MiB stack ($engine) failed"; }
done
cmp -s "$tmp/chain.jit.glb" "$tmp/chain.interp.glb" || fail "chain: the engines wrote other bytes"

# The REPL survives (and keeps its session).
timeout "$(watchdog 60)" "$fgsg" repl <"$inputs/04_repl_jit_crash.script" >"$tmp/repl.out" 2>&1
[ $? -lt 124 ] || { cat "$tmp/repl.out" >&2; fail "the REPL died deriving A ~> A A"; }
grep -q "R004" "$tmp/repl.out" || { cat "$tmp/repl.out" >&2; fail "the REPL did not report the limit"; }

# A Lock set that never ends: R017 at 2000 levels, also on a 2 MiB stack.
for engine in jit interp; do
  ( ulimit -s 2048; exec timeout 60 "$fgsg" run "$inputs/17_lock_never_ends_small_stack.fgsg" --engine=$engine -o "$tmp/l.glb" ) \
    >"$tmp/out" 2>"$tmp/err"
  code=$?
  [ $code -eq 1 ] || { cat "$tmp/err" >&2; fail "Lock on a small stack ($engine): exit $code, expected 1"; }
  grep -q "R017.*2000 shapes deep" "$tmp/err" || { cat "$tmp/err" >&2; fail "Lock: no R017"; }
done
echo "deep recursion: ok"

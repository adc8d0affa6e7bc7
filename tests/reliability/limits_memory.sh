#!/usr/bin/env bash
# --max-memory stops a runaway derivation with the kept-result warning (R004, exit 0)
# before memory runs out, counting the mesh its instances will become; bad sizes are
# usage errors.
. "$(dirname "$0")/lib.sh"
skip_under_asan "it measures memory against --max-memory"
export FGSG_CACHE_DIR=off

stopped='warning\[R004\]: derivation stopped at [0-9.]+M of memory \(--max-memory 200M, with the instances. mesh to come\): rule .A#0. \(applied [0-9]+ times\) ran away; the shapes derived so far are kept'
for engine in interp jit; do
  expect 0 "$stopped" -- "$fgsg" run "$inputs/limits_runaway.fgsg" --engine "$engine" --max-memory 200M \
    --max-depth 1000 --max-shapes 1000000000 -o "$tmp/runaway.glb"
  [ -s "$tmp/runaway.glb" ] || fail "the kept result was not written ($engine)"
done

# The process never holds much more than the budget (assembling and writing included).
[ -x /usr/bin/time ] ||
  fail "/usr/bin/time is missing: install Debian's time package (scripts/install-deps.sh --test does)"
peak=$( { /usr/bin/time -f '%M' "$fgsg" run "$inputs/limits_runaway.fgsg" --engine interp --max-memory 200M \
  --max-depth 1000 --max-shapes 1000000000 -o "$tmp/peak.glb" 2>&1 >/dev/null; } | tail -1)
[ "$peak" -lt 330000 ] || fail "peak resident memory ${peak} KB under --max-memory 200M"

# A doubling template L-system with --max-shapes past any memory: its buffers are sized
# within --max-memory and --max-memory stops it (10^12 reserved 16 TB up front, R020; 2^63 - 1
# and 2^63 wrapped the byte count, a crash; #48).
for shapes in 1000000000000 9223372036854775807 9223372036854775808 18446744073709551615; do
  expect 0 'warning\[R004\]: derivation stopped at [0-9.]+M of memory \(--max-memory 200M, with the instances. mesh to come\): rule .A#0. \(applied [0-9]+ times\) ran away' -- \
    "$fgsg" run "$inputs/limits_parallel_doubling.fgsg" --max-shapes "$shapes" --max-memory 200M -o "$tmp/doubling.obj"
done

for bad in 0 12X -5 1.5Q M ''; do
  expect 2 'fgsg run: --max-memory .*: expected a size such as 512M or 2G' -- \
    "$fgsg" run "$inputs/limits_runaway.fgsg" --max-memory "$bad"
done
expect 0 'derivation stopped at 1000 shapes' -- \
  "$fgsg" run "$inputs/limits_runaway.fgsg" --max-memory=1.5G --max-shapes 1000 -o "$tmp/ok.glb"
exit 0

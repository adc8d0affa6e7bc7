#!/usr/bin/env bash
# `fgsg synth` agrees with `fgsg run` (#47): the limit is --max-seconds (--time-limit still
# works and says once that it is deprecated), --stats prints run's `name value` lines, and
# with no model output named the mesh goes to EXAMPLE's stem + .glb here (never exit 0
# having written nothing). usage: synth_like_run.sh FGSG SOURCE_DIR
. "$(dirname "$0")/../reliability/lib.sh"
castle="$root/examples/synthesis/castle.txt" box="$root/examples/synthesis/continuous/box.obj"
cd "$tmp" || fail "no scratch folder"

# No output named: castle.glb in the current directory, as fgsg run writes FILE's stem.glb.
expect 0 '^wrote castle\.glb \(8 x 8 x 2 cells, [0-9]+ labels\)$' -- "$fgsg" synth "$castle" --size 8 8 2
[ -s castle.glb ] || fail "synth without -o wrote no castle.glb"
rm -f castle.glb
# A preview alone does not replace the model (run writes its default mesh beside it too).
expect 0 '^wrote castle\.glb, c\.png ' -- "$fgsg" synth "$castle" --size 8 8 2 --preview c.png
[ -s castle.glb ] && [ -s c.png ] || fail "synth --preview wrote no castle.glb and c.png"
rm -f castle.glb
# The label grid is a model output: it alone is written.
expect 0 '^wrote l\.txt ' -- "$fgsg" synth "$castle" --size 8 8 2 --labels l.txt
[ -e castle.glb ] && fail "synth --labels also wrote castle.glb"
# The continuous form: box.glb.
expect 0 '^wrote box\.glb \([1-9][0-9]* parts' -- "$fgsg" synth "$box" --size 10 10 4
[ -s box.glb ] || fail "continuous synth without -o wrote no box.glb"

# --max-seconds as run's; --time-limit its deprecated alias, said once even when repeated.
expect 2 '^fgsg synth: error: --max-seconds needs seconds greater than 0, at most 1e9$' -- \
  "$fgsg" synth "$castle" --size 8 8 2 --max-seconds 0
expect 2 '^fgsg synth: error: --max-seconds expects a number, got .x.$' -- \
  "$fgsg" synth "$box" --size 10 10 4 --max-seconds x
expect 0 '^wrote o\.glb' -- "$fgsg" synth "$castle" --size 8 8 2 --time-limit 5 --time-limit 6 -o o.glb
[ "$(grep -c 'deprecated' "$tmp/err")" = 1 ] || { cat "$tmp/err" >&2; fail "--time-limit not said deprecated exactly once"; }
grep -qx 'fgsg synth: warning: --time-limit is deprecated, use --max-seconds (as fgsg run)' "$tmp/err" ||
  fail "--time-limit's deprecation message changed"
expect 0 '^wrote o\.glb' -- "$fgsg" synth "$castle" --size 8 8 2 --max-seconds 5 -o o.glb
grep -q deprecated "$tmp/err" && fail "--max-seconds said deprecated"
# The limit is used: a large grid stops at it, by either name.
for flag in --max-seconds --time-limit; do
  expect 1 'error\[E740\]: synthesis failed: time limit' -- \
    "$fgsg" synth "$root/examples/synthesis/landscape.txt" --size 2000 2000 1 $flag 0.05 --labels big.txt
done

# --stats: fgsg run's format, `name value` lines on stdout, timings as time.NAME.
"$fgsg" synth "$castle" --size 8 8 2 --seed 3 -o o.glb --stats >stats 2>err || { cat err >&2; fail "synth --stats failed"; }
grep -vqE '^[a-z.]+ [0-9]+(\.[0-9]+)?$' stats && { cat stats >&2; fail "a --stats line is not 'name value'"; }
for line in 'consistent 1' 'size.x 8' 'size.y 8' 'size.z 2' 'blocks.failed 0'; do
  grep -qx "$line" stats || { cat stats >&2; fail "synth --stats lacks '$line'"; }
done
grep -qE '^time\.synthesize [0-9]+\.[0-9]{6}$' stats || fail "synth --stats lacks time.synthesize"
"$fgsg" synth "$box" --size 10 10 4 -o b.obj --stats >cstats 2>err || { cat err >&2; fail "continuous --stats failed"; }
grep -vqE '^[a-z.]+ [0-9]+(\.[0-9]+)?$' cstats && { cat cstats >&2; fail "a continuous --stats line is not 'name value'"; }
for name in example.polygons output.polygons parts time.synthesize time.surface; do
  grep -qE "^$name [0-9]" cstats || { cat cstats >&2; fail "continuous --stats lacks $name"; }
done
grep -qx 'example.polygons 6' cstats || { cat cstats >&2; fail "box.obj is not 6 polygons in --stats"; }
# The same line shape as fgsg run --stats (its time.engine names the engine).
printf 'axiom: S(1, 1, 1) I("cube");\n' >cube.fgsg
"$fgsg" run cube.fgsg -o cube.glb --stats -q >rstats 2>err || { cat err >&2; fail "run --stats failed"; }
grep -v '^time.engine ' rstats | grep -vqE '^[a-z.]+ [0-9]+(\.[0-9]+)?$' && { cat rstats >&2; fail "run's --stats format changed"; }
grep -qE '^time\.derive [0-9]+\.[0-9]{6}$' rstats || fail "run's time lines changed"
exit 0

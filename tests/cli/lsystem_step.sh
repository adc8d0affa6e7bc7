#!/usr/bin/env bash
# fgsg run --step N (#48, lpfg's animate mode): an L-system derived N steps instead of its
# length. F -> F [ + F ] F [ - F ] F turns each F into 5, so step k draws 5^k segments
# (counted by hand: 1, 5, 25, 125), each a ribbon of 2 triangles; step = the length is
# the run without --step, byte for byte; the interpreter and the JIT write the same bytes
# at every step; past the length the length is derived with a warning; a bad N, or --step
# on a grammar that is no L-system, is a usage error (exit 2) that writes nothing.
. "$(dirname "$0")/../reliability/lib.sh"
cat >"$tmp/plant.fgsg" <<'EOF'
derive parallel 3;
turtle angle 25.7 segments "ribbons";
axiom: F;
F -> F [ + F ] F [ - F ] F;
EOF

# "wrote FILE (N instances, T triangles[, L line segments])" -> "N T L"
drawn() { sed -nE 's/^wrote .* \(([0-9]+) instances, ([0-9]+) triangles(, ([0-9]+) line segments)?\).*/\1 \2 \4/p' "$1"; }

segments=(1 5 25 125)
for k in 0 1 2 3; do
  for engine in jit interp; do
    "$fgsg" run "$tmp/plant.fgsg" --step "$k" --engine "$engine" -o "$tmp/$engine$k.glb" 2>"$tmp/err" \
      || { cat "$tmp/err" >&2; fail "--step $k --engine $engine failed"; }
    got=$(drawn "$tmp/err")
    want="${segments[$k]} $((2 * segments[k])) "
    [ "$got" = "$want" ] || fail "--step $k --engine $engine: drew '$got' (instances triangles), expected '$want'"
  done
  cmp "$tmp/jit$k.glb" "$tmp/interp$k.glb" || fail "--step $k: the interpreter and the JIT wrote other bytes"
done
"$fgsg" run "$tmp/plant.fgsg" -q -o "$tmp/whole.glb" || fail "the run without --step failed"
cmp "$tmp/whole.glb" "$tmp/jit3.glb" || fail "--step 3 (the length) is not the run without --step"
cmp -s "$tmp/jit2.glb" "$tmp/jit3.glb" && fail "--step 2 and --step 3 wrote the same bytes"

# Past the length: the length, said once (and not with -q).
expect 0 "warning: --step 7 is past .*plant.fgsg's derivation length 3: step 3, its last, is derived" \
  -- "$fgsg" run "$tmp/plant.fgsg" --step 7 -o "$tmp/past.glb"
cmp "$tmp/past.glb" "$tmp/whole.glb" || fail "--step 7 is not the length's derivation"
"$fgsg" run "$tmp/plant.fgsg" --step 7 -q -o "$tmp/past.glb" 2>"$tmp/err" || fail "--step 7 -q failed"
[ -s "$tmp/err" ] && fail "-q still printed: $(cat "$tmp/err")"

# The length an attr gives (ABOP Fig. 1.24a: derive parallel n, segments "lines"):
# --set n=2 makes 2 the last step.
fig="$root/examples/abop/fig1_24a.fgsg"
"$fgsg" run "$fig" --step 2 -o "$tmp/fig.glb" 2>"$tmp/err" || fail "fig1_24a --step 2 failed"
[ "$(drawn "$tmp/err")" = "25 0 25" ] || fail "fig1_24a --step 2: drew '$(drawn "$tmp/err")', expected 25 segments as lines"
expect 0 "--step 4 is past .*fig1_24a.fgsg's derivation length 2" \
  -- "$fgsg" run "$fig" --set n=2 --step 4 -o "$tmp/fig4.glb"
[ "$(drawn "$tmp/err")" = "25 0 25" ] || fail "--set n=2 --step 4: drew '$(drawn "$tmp/err")', expected step 2's 25 lines"
"$fgsg" run "$fig" --set n=2 -q -o "$tmp/fig2.glb" || fail "fig1_24a --set n=2 failed"
cmp "$tmp/fig2.glb" "$tmp/fig4.glb" || fail "--set n=2 --step 4 is not the run with --set n=2"
expect 1 "R010.*n=two: expected a number" -- "$fgsg" run "$fig" --set n=two --step 1 -o "$tmp/bad.glb"

# Bad values and grammars: usage errors, nothing written.
expect 2 "--step expects a whole number from 0 to 2147483647, got '-1'" -- "$fgsg" run "$tmp/plant.fgsg" --step=-1 -o "$tmp/bad.glb"
expect 2 "--step expects a whole number from 0 to 2147483647, got 'two'" -- "$fgsg" run "$tmp/plant.fgsg" --step two -o "$tmp/bad.glb"
expect 2 "--step expects a whole number from 0 to 2147483647, got '1.5'" -- "$fgsg" run "$tmp/plant.fgsg" --step 1.5 -o "$tmp/bad.glb"
expect 2 "--step 1: .*stepped_column.fgsg is no L-system" -- "$fgsg" run "$root/examples/stepped_column.fgsg" --step 1 -o "$tmp/bad.glb"
[ -e "$tmp/bad.glb" ] && fail "a refused --step wrote output"
echo "ok: fgsg run --step"

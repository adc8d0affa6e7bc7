#!/usr/bin/env bash
# Synthesize() naming a tile set with a bad field (reproducer 11): `fgsg check` finds it,
# and `fgsg run` reports it at the call with both engines (R013, not an abort or R900).
. "$(dirname "$0")/lib.sh"
grammar="$inputs/inputs_11_synthesize_bad_tileset.fgsg"
at='inputs_11_synthesize_bad_tileset.fgsg:1:19: error\[R013\]: Synthesize: cannot use the example "inputs_11_bad_sym.json":'
why='inputs_11_bad_sym.json:1: error\[E712\]: tile `a`: "symmetry" must be a symmetry class'
for engine in interp jit; do
  expect 1 "$at" -- "$fgsg" run "$grammar" --engine=$engine -o "$tmp/x.glb"
  grep -qE -- "$why" "$tmp/err" || fail "run --engine=$engine does not give the tile set's error"
  grep -q 'R900' "$tmp/err" && fail "run --engine=$engine blames the JIT"
  [ ! -e "$tmp/x.glb" ] || fail "run --engine=$engine wrote an output"
  same_message "$fgsg" run "$grammar" --engine=$engine -o "$tmp/x.glb"
done
cp "$tmp/err" "$tmp/run.err"
expect 1 "$at" -- "$fgsg" check "$grammar"
grep -qE -- "$why" "$tmp/err" || fail "check does not give the tile set's error"
grep -q '^1 error in .*inputs_11_synthesize_bad_tileset.fgsg$' "$tmp/err" || fail "check: no error count"
# The same diagnostic from both commands (check adds only its count).
diff <(grep -v ' error in ' "$tmp/err") "$tmp/run.err" >&2 || fail "check and run report it differently"
# A good tile set passes check.
cat > "$tmp/good.json" <<'JSON'
{"tiles": [{"name": "a", "symmetry": "X"}], "neighbors": [{"left": "a", "right": "a"}]}
JSON
printf 'axiom: S(4, 1, 4) Synthesize("good.json", 2, 2, 1);\n' > "$tmp/good.fgsg"
timeout 60 "$fgsg" check "$tmp/good.fgsg" > "$tmp/out" 2>&1 || { cat "$tmp/out" >&2; fail "check refuses a good tile set"; }
# A missing one is found by check as by run.
printf 'axiom: S(4, 1, 4) Synthesize("missing.json", 2, 2, 1);\n' > "$tmp/missing.fgsg"
expect 1 'missing.fgsg:1:19: error\[R013\]: Synthesize: cannot use the example "missing.json"' -- "$fgsg" check "$tmp/missing.fgsg"
exit 0

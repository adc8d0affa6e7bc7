#!/usr/bin/env bash
# fgsg evolve as a user meets it: the GA's per-generation report and its best L-system,
# reproducible by seed; a p4 search that ends with a p4 pattern; --lsystem expands the
# paper's own string to the exact pattern; --json and --preview written whole; bad flags
# are usage errors (2), bad files and strings errors (1) naming the problem.
. "$(dirname "$0")/../reliability/lib.sh"
tiles="$root/examples/assets/ornament_tiles.json"
json_value() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

# The paper's Fig. 2 string: A -> AB/AA, B -> AB/BA, axiom A; generation 2 by hand.
"$fgsg" evolve "$tiles" --lsystem '{ABAA.ABBA.A}' --generation 2 --json "$tmp/fig2.json" >"$tmp/out" ||
  fail "--lsystem: exit $?"
[ "$(head -1 "$tmp/out")" = "{ABAA.ABBA.A}" ] || fail "--lsystem: first line $(head -1 "$tmp/out")"
[ "$(json_value "$tmp/fig2.json" "' '.join(d['pattern'])")" = "ABAB AABA ABAB AAAA" ] ||
  fail "generation 2 of {ABAA.ABBA.A}: $(json_value "$tmp/fig2.json" "d['pattern']")"
[ "$(json_value "$tmp/fig2.json" "'history' in d")" = False ] || fail "--lsystem ran a GA"

# A p4 search: the report has one line per generation, the best is a p4 pattern, and the
# same seed gives the same run.
"$fgsg" evolve "$tiles" --p4 --seed 3 --json "$tmp/p4.json" --preview "$tmp/p4.png" >"$tmp/run1" ||
  fail "--p4: exit $?"
[ "$(json_value "$tmp/p4.json" "d['terms']['p4']")" = 1.0 ] || fail "--p4: the best is no p4 pattern"
[ "$(json_value "$tmp/p4.json" "d['stop']")" = threshold ] || fail "--p4: stopped by $(json_value "$tmp/p4.json" "d['stop']")"
generations=$(json_value "$tmp/p4.json" "d['generations']")
rows=$(grep -cE '^ +[0-9]+  [01]\.[0-9]{4}  ' "$tmp/run1")
[ "$rows" -eq $((generations + 1)) ] || fail "$rows report lines for $generations generations (+ the first population)"
[ "$(json_value "$tmp/p4.json" "len(d['pattern'])")" = 81 ] || fail "generation 4 of 3x3 rules is not 81 cells a side"
width=$(od -An -tu1 -j16 -N4 "$tmp/p4.png" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
[ "$width" = 2592 ] || fail "the preview is $width pixels wide, expected 81 cells x 32"
"$fgsg" evolve "$tiles" --p4 --seed 3 >"$tmp/run2" || fail "second run: exit $?"
diff <(grep -v ' s: ' "$tmp/run1" | grep -v '^wrote') <(grep -v ' s: ' "$tmp/run2") >/dev/null ||
  fail "the same seed gave another run"
[ "$("$fgsg" evolve "$tiles" --p4 --seed 3 -q)" = "$(head -n $((generations + 3)) "$tmp/run1" | tail -1)" ] ||
  fail "-q does not print just the L-system"
"$fgsg" evolve "$tiles" --seed 4 -q >"$tmp/seed4"
cmp -s "$tmp/seed4" <("$fgsg" evolve "$tiles" --seed 5 -q) && fail "seeds 4 and 5 gave the same L-system"

# Errors: evolve_fails CODE PATTERN ARGS... (lib.sh's expect on `fgsg evolve ARGS`).
evolve_fails() {
  local code=$1 pattern=$2
  shift 2
  expect "$code" "$pattern" -- "$fgsg" evolve "$@"
}
evolve_fails 2 "no tile file given"
evolve_fails 2 "--k expects a whole number from 1 to 16, got '0'" "$tiles" --k 0
evolve_fails 2 "unknown option '--bogus'" "$tiles" --bogus
evolve_fails 2 "--mutation expects a probability from 0 to 1" "$tiles" --mutation 2
evolve_fails 2 "--weights expects a,b,c or a,b,c,d" "$tiles" --weights 1,2
evolve_fails 2 "previews are PNG files" "$tiles" --preview x.jpg
evolve_fails 1 "column 4: unknown symbol 'C'" "$tiles" --lsystem '{ABCA.ABBA.A}'
evolve_fails 1 "no such file" "$tmp/none.json"
echo '{"loci": 3}' >"$tmp/bad.json"
evolve_fails 1 "bad.json: " "$tmp/bad.json"
evolve_fails 1 "ran out before the first population" "$tiles" --population 100000 --max-seconds 0.001
evolve_fails 1 "a pattern of 2048 cells a side is too large to draw" "$tiles" --lsystem '{ABAA.ABBA.A}' --generation 11 \
  --preview "$tmp/big.png"
[ -e "$tmp/big.png" ] && fail "a refused preview was written"
evolve_fails 1 "cannot write '$tmp/missing/x.json'" "$tiles" --max-generations 1 --json "$tmp/missing/x.json"

# A grammar's declared tileset is checked as a tile file is: by `fgsg check` before any run,
# at its item, and `fgsg run` says the same.
printf 'tileset t {\n  locus a = polyline((0, 0.5), (1, 0.5));\n  section r = polyline((-1, 0), (1, 0.5));\n}\naxiom: Evolve(t, 2)\n' \
  >"$tmp/bad_tileset.fgsg"
for cmd in check run; do
  out=()
  [ $cmd = run ] && out=(-o "$tmp/never.glb")
  "$fgsg" $cmd "$tmp/bad_tileset.fgsg" "${out[@]}" >/dev/null 2>"$tmp/err"
  [ $? -eq 1 ] || fail "fgsg $cmd of a bad tileset: exit code"
  grep -q "bad_tileset.fgsg:3:3: error\[R025\]: Evolve: tileset 't': sections\[0\].polyline: a cross-section runs from (-1, 0) to (1, 0)" "$tmp/err" ||
    { cat "$tmp/err" >&2; fail "fgsg $cmd of a bad tileset: message"; }
done
[ -e "$tmp/never.glb" ] && fail "a failed run wrote its output"
"$fgsg" check "$root/examples/evolve_tiles.fgsg" >/dev/null 2>&1 || fail "fgsg check examples/evolve_tiles.fgsg failed"
exit 0

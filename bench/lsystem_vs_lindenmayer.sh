#!/usr/bin/env bash
# fgsg's L-system rewriting side by side with npm `lindenmayer` (JavaScript), in one run:
# the two tools alternate ROUNDS times on the same machine, and the script prints each
# round's ratios and their medians (issue 48: a ratio is only ever reported from one such
# run, never against a figure measured elsewhere). Like is set beside like:
#
#   warm  both in process, their code compiled, after a first repetition: lindenmayer's
#         fastest of 6 repetitions in one node process against fgsg's fastest of 6 in one
#         `bench_lsystem --warm` process (the grammar compiled by the JIT once, each
#         repetition a whole derivation, its `time.rewrite` / `time.derive`);
#         The rewriting's product is the whole derived string on both sides: lindenmayer's
#         iterate() appends each successor with `+=` (string productions), which V8 keeps
#         as a rope, one node per append, flattened into one array of characters when it
#         is first read; each step reads the last step's string, so only the final one
#         would be left a rope, and the script reads its last character inside the time
#         (measured on this machine: 0.2 ms of the plant's 1.5-2 ms, 8-15 ms of F -> FFF's
#         100-180 ms). fgsg's `time.rewrite` ends with its string as an array of 16-byte
#         modules (op, first argument, random key), before the turtle reads it;
#   cold  a whole process each, its start-up included, wall clock: `node` deriving once
#         against `fgsg run` (code cache filled by one run before the rounds). Each makes
#         the same product: for F -> FFF the string (fgsg writes an empty .glb); for the
#         plant its segments in a file — fgsg a .glb, lindenmayer their end points as
#         32-bit floats (its string has no mesh format) — both in /dev/shm where there is
#         one, because on a disk fgsg's fsync of its output, 0.1-0.2 s on this VM, would
#         be most of what is measured.
# Same work: before the rounds the script checks that the two derive the same thing —
# equal module counts (fgsg's modules, lindenmayer's string length: for F -> FFF that is
# the whole string, 3^13 copies of one symbol) and, for the plant, the same 38 342
# segments in the same order, end points equal to 1e-9 (fgsg's `--instances`, which also
# fixes the string's F + - [ ] up to the X's that draw nothing) — and stops if not.
#
#   bench/lsystem_vs_lindenmayer.sh [FGSG] [ROUNDS]   (defaults: build/bin/fgsg, 5;
#                                                      bench_lsystem beside FGSG)
# Workloads:
#   fff   axiom F, F -> F F F, 13 steps (1 594 323 modules), the string only (fgsg's
#         symbol is A, which the turtle does not draw, so nothing but the string is made);
#   plant ABOP Fig. 1.24d, X -> F[+X]F[-X]+X, F -> FF, 9 steps (126 912 modules): the
#         rewriting alone (warm only) and the whole derivation with the turtle's segments.
# lindenmayer is installed with npm into $LINDENMAYER_DIR (default /tmp/fgsg-lindenmayer)
# on first use.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fgsg=${1:-$root/build/bin/fgsg}
rounds=${2:-5}
bench=$(dirname "$fgsg")/bench_lsystem
[ -x "$bench" ] || { echo "no $bench: build the bench_lsystem target" >&2; exit 2; }
scratch=${LINDENMAYER_DIR:-/tmp/fgsg-lindenmayer}
mkdir -p "$scratch"
if [ ! -d "$scratch/node_modules/lindenmayer" ]; then
  (cd "$scratch" && npm install --no-audit --no-fund lindenmayer >/dev/null) ||
    { echo "npm could not install lindenmayer into $scratch" >&2; exit 2; }
fi

cat > "$scratch/side_by_side.js" <<'JS'
// node side_by_side.js fff|plant N REPS [SEGMENTS_FILE]: prints the fastest seconds as
// JSON; with SEGMENTS_FILE the plant's segments are also written there (x0 y0 0 x1 y1 0
// as 32-bit floats per segment), inside the time.
const LSystem = require('lindenmayer');
const fs = require('fs');
const [, , workload, steps, repsText, segmentsFile] = process.argv;
const n = parseInt(steps, 10), reps = parseInt(repsText, 10);
const whole = [], rewrite = [];
let length = 0, segments = 0, last = 0;
for (let r = 0; r < reps; r++) {
  const t0 = process.hrtime.bigint();
  if (workload === 'fff') {
    const string = new LSystem({axiom: 'F', productions: {F: 'FFF'}}).iterate(n);
    last = string.charCodeAt(string.length - 1);  // flattens V8's rope (see the header)
    length = string.length;
    const s = Number(process.hrtime.bigint() - t0) / 1e9;
    whole.push(s), rewrite.push(s);
    continue;
  }
  // ABOP Fig. 1.24d with a 2D turtle drawing unit segments, 20 degrees.
  const out = [], stack = [], turn = 20 * Math.PI / 180;
  let x = 0, y = 0, a = Math.PI / 2;
  const ls = new LSystem({
    axiom: 'X', productions: {X: 'F[+X]F[-X]+X', F: 'FF'},
    finals: {
      F: () => { const nx = x + Math.cos(a), ny = y + Math.sin(a); out.push(x, y, nx, ny); x = nx; y = ny; },
      '+': () => { a += turn; }, '-': () => { a -= turn; },
      '[': () => { stack.push([x, y, a]); }, ']': () => { [x, y, a] = stack.pop(); },
    }});
  const string = ls.iterate(n);
  last = string.charCodeAt(string.length - 1);  // flattens V8's rope (see the header)
  length = string.length;
  const t1 = process.hrtime.bigint();
  ls.final();
  segments = out.length / 4;
  if (segmentsFile) {
    const points = new Float32Array(segments * 6);
    for (let i = 0; i < segments; i++)
      points.set([out[4 * i], out[4 * i + 1], 0, out[4 * i + 2], out[4 * i + 3], 0], 6 * i);
    fs.writeFileSync(segmentsFile, points);
  }
  rewrite.push(Number(t1 - t0) / 1e9);
  whole.push(Number(process.hrtime.bigint() - t0) / 1e9);
}
const fastest = (v) => Math.min(...v);
console.log(JSON.stringify({length, segments, last, rewrite_s: fastest(rewrite), whole_s: fastest(whole)}));
JS

cat > "$scratch/same_work.js" <<'JS'
// node same_work.js INSTANCES_JSON: lindenmayer's Fig. 1.24d n=9 segments (as
// side_by_side.js draws them) against fgsg's instances (a line's unit box: start at the
// transform's translation, end one Y column further). Prints the comparison; exit 1 if
// the segments differ in number, order or end points (beyond 1e-9).
const LSystem = require('lindenmayer');
const fs = require('fs');
const fgsg = JSON.parse(fs.readFileSync(process.argv[2], 'utf8')).instances;
const out = [], stack = [], turn = 20 * Math.PI / 180;
let x = 0, y = 0, a = Math.PI / 2;
const ls = new LSystem({
  axiom: 'X', productions: {X: 'F[+X]F[-X]+X', F: 'FF'},
  finals: {
    F: () => { const nx = x + Math.cos(a), ny = y + Math.sin(a); out.push([x, y, nx, ny]); x = nx; y = ny; },
    '+': () => { a += turn; }, '-': () => { a -= turn; },
    '[': () => { stack.push([x, y, a]); }, ']': () => { [x, y, a] = stack.pop(); },
  }});
const string = ls.iterate(9);
ls.final();
let worst = 0;
if (fgsg.length === out.length)
  fgsg.forEach((inst, i) => {
    const t = inst.transform, s = out[i];
    const theirs = [t[12], t[13], t[12] + t[4], t[13] + t[5]];
    worst = Math.max(worst, Math.abs(t[14]), Math.abs(t[14] + t[6]), ...theirs.map((v, k) => Math.abs(v - s[k])));
  });
const same = fgsg.length === out.length && worst <= 1e-9;
console.log(`plant: lindenmayer ${string.length} modules, ${out.length} segments; fgsg ${fgsg.length} segments; ` +
            `largest end point difference ${worst.toExponential(1)}: ${same ? 'same' : 'DIFFERENT'}`);
process.exit(same ? 0 : 1);
JS

cat > "$scratch/fff13.fgsg" <<'FGSG'
derive parallel 13;
axiom: A;
A -> A A A;
FGSG
cat > "$scratch/plant9.fgsg" <<'FGSG'
derive parallel 9;
turtle angle 20 step 1 width 0.1 segments "lines";
axiom: X;
X -> F [ + X ] F [ - X ] + X;
F -> F F;
FGSG

field() { echo "$1" | sed "s/.*\"$2\":\([0-9.e-]*\).*/\1/"; }
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }
# Wall seconds of one command, its output discarded.
wall() {
  local t0 t1
  t0=$(date +%s%N)
  "$@" > /dev/null
  t1=$(date +%s%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.4f", (b - a) / 1e9}'
}

tmp=$(mktemp -d)
out=$(mktemp -d -p /dev/shm 2>/dev/null || mktemp -d)
trap 'rm -rf "$tmp" "$out"' EXIT
export FGSG_CACHE_DIR=$tmp/cache
"$fgsg" run "$scratch/fff13.fgsg" -o "$out/fff.glb" -q
"$fgsg" run "$scratch/plant9.fgsg" -o "$out/plant.glb" -q
# Same work (not timed): module counts, and the plant's segments one by one.
js_fff=$(cd "$scratch" && node side_by_side.js fff 13 1)
fg_fff=$("$bench" --warm "$scratch/fff13.fgsg" 1)
js_plant=$(cd "$scratch" && node side_by_side.js plant 9 1)
fg_plant=$("$bench" --warm "$scratch/plant9.fgsg" 1)
for pair in "fff $(field "$js_fff" length) $(field "$fg_fff" modules)" \
  "plant $(field "$js_plant" length) $(field "$fg_plant" modules)"; do
  set -- $pair
  echo "same work: $1: lindenmayer's string $2 modules, fgsg's $3"
  [ "$2" = "$3" ] || { echo "the two tools derive strings of different lengths" >&2; exit 1; }
done
"$fgsg" run "$scratch/plant9.fgsg" -o "$out/plant.glb" -q --instances "$out/plant.json"
(cd "$scratch" && node same_work.js "$out/plant.json") || exit 1
rm -f "$out/plant.json"
echo "warm: in process, 6 derivations each, the first one also the warm-up (V8's JIT;"
echo "      fgsg's grammar JIT-compiled once before them), the fastest of the 6 reported;"
echo "cold: a whole process each, wall clock, each writing its product (see the header)."
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
# Columns: warm fff rewrite, warm plant rewrite, warm plant whole, cold fff, cold plant;
# each lindenmayer's seconds / fgsg's seconds = ratio.
for r in $(seq 1 "$rounds"); do
  js_fff=$(cd "$scratch" && node side_by_side.js fff 13 6)
  fg_fff=$("$bench" --warm "$scratch/fff13.fgsg" 6)
  js_plant=$(cd "$scratch" && node side_by_side.js plant 9 6)
  fg_plant=$("$bench" --warm "$scratch/plant9.fgsg" 6)
  jc_fff=$(cd "$scratch" && wall node side_by_side.js fff 13 1)
  fc_fff=$(wall "$fgsg" run "$scratch/fff13.fgsg" -o "$out/fff.glb" -q)
  jc_plant=$(cd "$scratch" && wall node side_by_side.js plant 9 1 "$out/plant.bin")
  fc_plant=$(wall "$fgsg" run "$scratch/plant9.fgsg" -o "$out/plant.glb" -q)
  set -- "$(field "$js_fff" rewrite_s)" "$(field "$fg_fff" rewrite_s)" \
    "$(field "$js_plant" rewrite_s)" "$(field "$fg_plant" rewrite_s)" \
    "$(field "$js_plant" whole_s)" "$(field "$fg_plant" derive_s)" \
    "$jc_fff" "$fc_fff" "$jc_plant" "$fc_plant"
  echo "$1 $2 $3 $4 $5 $6 $7 $8 $9 ${10}" >> "$tmp/times"
  printf 'round %s  warm: fff %s/%s = %sx  plant rewrite %s/%s = %sx  plant+turtle %s/%s = %sx\n' "$r" \
    "$1" "$2" "$(ratio "$1" "$2")" "$3" "$4" "$(ratio "$3" "$4")" "$5" "$6" "$(ratio "$5" "$6")"
  printf '          cold: fff %s/%s = %sx  plant+turtle %s/%s = %sx\n' \
    "$7" "$8" "$(ratio "$7" "$8")" "$9" "${10}" "$(ratio "$9" "${10}")"
done
echo "lindenmayer's last: $js_fff; $js_plant"
echo "fgsg's last: $fg_fff; $fg_plant"
col() { awk -v c="$1" '{print $c}' "$tmp/times" | median; }
rcol() { awk -v a="$1" -v b="$2" '{printf "%.6f\n", $a / $b}' "$tmp/times" | median; }
echo "medians over $rounds rounds (ratio: lindenmayer's time / fgsg's; above 1: fgsg is faster):"
printf '  warm  F -> FFF n=13, rewriting:             %s s / %s s, ratio %.2f\n' "$(col 1)" "$(col 2)" "$(rcol 1 2)"
printf '  warm  ABOP Fig. 1.24d n=9, rewriting:       %s s / %s s, ratio %.2f\n' "$(col 3)" "$(col 4)" "$(rcol 3 4)"
printf '  warm  ABOP Fig. 1.24d n=9, with the turtle: %s s / %s s, ratio %.2f\n' "$(col 5)" "$(col 6)" "$(rcol 5 6)"
printf '  cold  F -> FFF n=13, whole process:         %s s / %s s, ratio %.2f\n' "$(col 7)" "$(col 8)" "$(rcol 7 8)"
printf '  cold  ABOP Fig. 1.24d n=9, whole process:   %s s / %s s, ratio %.2f\n' "$(col 9)" "$(col 10)" "$(rcol 9 10)"
awk '{print 1594323 / $2 / 1e6}' "$tmp/times" | median | xargs printf '  fgsg warm template rewriting, F -> FFF n=13: %.0f M modules/s\n'
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"

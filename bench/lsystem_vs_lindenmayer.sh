#!/usr/bin/env bash
# fgsg's L-system rewriting side by side with npm `lindenmayer` (JavaScript), in one run:
# the two tools alternate ROUNDS times on the same machine, and the script prints each
# round's ratio (lindenmayer's warm time over fgsg's) and their median (issue 48: a ratio
# is only ever reported from one such run, never against a figure measured elsewhere).
#
#   bench/lsystem_vs_lindenmayer.sh [FGSG] [ROUNDS]     (defaults: build/fgsg, 5)
#
# Workloads:
#   fff   axiom F, F -> F F F, 13 steps (1 594 323 modules), the string only: lindenmayer's
#         iterate() against fgsg's `time.rewrite` (fgsg's symbol is A, which the turtle
#         does not draw, so that nothing but the string is made: the same rewriting);
#   plant ABOP Fig. 1.24d, X -> F[+X]F[-X]+X, F -> FF, 9 steps (126 912 modules): the
#         rewriting alone (iterate() against `time.rewrite`), and the whole derivation with
#         the turtle's segments (iterate() + final() against `time.derive`).
# lindenmayer's time is the fastest of 6 repetitions in one node process (warm: its
# code compiled by V8); fgsg's is one `fgsg run --stats` (its grammar compiled by the JIT,
# the object cache warm after the first round). lindenmayer is installed with npm into
# $LINDENMAYER_DIR (default /tmp/fgsg-lindenmayer) on first use.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fgsg=${1:-$root/build/fgsg}
rounds=${2:-5}
scratch=${LINDENMAYER_DIR:-/tmp/fgsg-lindenmayer}
mkdir -p "$scratch"
if [ ! -d "$scratch/node_modules/lindenmayer" ]; then
  (cd "$scratch" && npm install --no-audit --no-fund lindenmayer >/dev/null) ||
    { echo "npm could not install lindenmayer into $scratch" >&2; exit 2; }
fi

cat > "$scratch/side_by_side.js" <<'EOF'
// node side_by_side.js fff|plant N REPS: prints the fastest and median seconds as JSON.
const LSystem = require('lindenmayer');
const [, , workload, steps, repsText] = process.argv;
const n = parseInt(steps, 10), reps = parseInt(repsText, 10);
const whole = [], rewrite = [];
let length = 0, segments = 0;
for (let r = 0; r < reps; r++) {
  const t0 = process.hrtime.bigint();
  if (workload === 'fff') {
    length = new LSystem({axiom: 'F', productions: {F: 'FFF'}}).iterate(n).length;
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
  length = ls.iterate(n).length;
  const t1 = process.hrtime.bigint();
  ls.final();
  segments = out.length / 4;
  rewrite.push(Number(t1 - t0) / 1e9);
  whole.push(Number(process.hrtime.bigint() - t0) / 1e9);
}
const fastest = (v) => Math.min(...v);
console.log(JSON.stringify({length, segments, rewrite_s: fastest(rewrite), whole_s: fastest(whole)}));
EOF

cat > "$scratch/fff13.fgsg" <<'EOF'
derive parallel 13;
axiom: A;
A -> A A A;
EOF
cat > "$scratch/plant9.fgsg" <<'EOF'
derive parallel 9;
turtle angle 20 step 1 width 0.1 segments "lines";
axiom: X;
X -> F [ + X ] F [ - X ] + X;
F -> F F;
EOF

stat() { grep "^$2 " "$1" | awk '{print $2}'; }
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-6s %-26s %-26s %-34s\n' round "fff13 rewrite (js/fgsg)" "plant9 rewrite (js/fgsg)" "plant9 with turtle (js/fgsg)"
for r in $(seq 1 "$rounds"); do
  js_fff=$(cd "$scratch" && node side_by_side.js fff 13 6)
  "$fgsg" run "$scratch/fff13.fgsg" -o "$tmp/fff.obj" --stats -q > "$tmp/fff.stats"
  js_plant=$(cd "$scratch" && node side_by_side.js plant 9 6)
  "$fgsg" run "$scratch/plant9.fgsg" -o "$tmp/plant.obj" --stats -q > "$tmp/plant.stats"
  jf=$(echo "$js_fff" | sed 's/.*"rewrite_s":\([0-9.e-]*\).*/\1/')
  jpr=$(echo "$js_plant" | sed 's/.*"rewrite_s":\([0-9.e-]*\).*/\1/')
  jpw=$(echo "$js_plant" | sed 's/.*"whole_s":\([0-9.e-]*\).*/\1/')
  ff=$(stat "$tmp/fff.stats" time.rewrite)
  fpr=$(stat "$tmp/plant.stats" time.rewrite)
  fpw=$(stat "$tmp/plant.stats" time.derive)
  echo "$(ratio "$jf" "$ff") $(ratio "$jpr" "$fpr") $(ratio "$jpw" "$fpw")" >> "$tmp/ratios"
  printf '%-6s %-26s %-26s %-34s\n' "$r" "$jf/$ff = $(ratio "$jf" "$ff")x" "$jpr/$fpr = $(ratio "$jpr" "$fpr")x" \
    "$jpw/$fpw = $(ratio "$jpw" "$fpw")x"
done
echo "lindenmayer: $js_fff; $js_plant"
echo "median ratio (lindenmayer's time / fgsg's; above 1: fgsg is faster):"
echo "  F -> FFF n=13, rewriting:            $(cut -d' ' -f1 "$tmp/ratios" | median)"
echo "  ABOP Fig. 1.24d n=9, rewriting:      $(cut -d' ' -f2 "$tmp/ratios" | median)"
echo "  ABOP Fig. 1.24d n=9, with the turtle: $(cut -d' ' -f3 "$tmp/ratios" | median)"
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"

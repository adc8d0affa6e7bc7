#!/usr/bin/env bash
# examples/synthesis/summer_like.json is what scripts/make_summer_like.py writes (the
# tile set's neighbour rules are derived, never edited by hand), and it synthesizes a
# 100x100 model on the first attempt in scanline order (bench_synthesis --orientations
# measures both orders over 100 seeds).
. "$(dirname "$0")/../reliability/lib.sh"
cd "$root" || fail "no source folder"
python3 scripts/make_summer_like.py >"$tmp/summer_like.json" || fail "make_summer_like.py failed"
cmp -s "$tmp/summer_like.json" examples/synthesis/summer_like.json ||
  fail "examples/synthesis/summer_like.json is not what scripts/make_summer_like.py writes"
for seed in 1 2 3; do
  "$fgsg" synth examples/synthesis/summer_like.json --size 100 100 1 --attempts 1 --seed $seed \
    --labels "$tmp/labels.txt" 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "seed $seed: scanline order failed"; }
done
echo "ok: summer_like"

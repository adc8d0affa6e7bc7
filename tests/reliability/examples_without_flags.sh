#!/usr/bin/env bash
# Every shipped example runs as `fgsg run examples/NAME.fgsg`, without limit flags, and
# ends by its own design: exit 0 and no R004 (no limit reached). Grammars that grow
# without end bound themselves (`derive breadthfirst N;`, `collision all;`); before, FGSG
# Fig. 1 and Fig. 4 ran into --max-seconds or the memory budget after minutes.
. "$(dirname "$0")/lib.sh"
export FGSG_CACHE_DIR=off
for example in "$root"/examples/*.fgsg; do
  name=$(basename "$example" .fgsg)
  # --max-seconds 50 only so that a regression fails here instead of hanging the suite.
  (cd "$tmp" && timeout 60 "$fgsg" run "$example" --max-seconds 50 -q -o "$tmp/$name.glb") 2>"$tmp/err"
  rc=$?
  [ $rc -eq 0 ] || { cat "$tmp/err" >&2; fail "$name: exit $rc"; }
  if grep -q 'R004' "$tmp/err"; then cat "$tmp/err" >&2; fail "$name reached a limit"; fi
  [ -s "$tmp/$name.glb" ] || fail "$name wrote nothing"
done
exit 0

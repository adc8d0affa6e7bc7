#!/usr/bin/env bash
# fgsg synth's outputs (--labels, -o, --preview) are one transaction: one that cannot be
# written keeps the others' old contents, and no temporary is left.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
cd "$tmp" || fail "no scratch folder"
ex="$root/examples/synthesis/roads.json"

echo "old labels" > l.txt
expect 1 "error\[E744\]: cannot write 'missing/r.glb': No such file or directory \(the folder missing does not exist\)" -- \
  "$fgsg" synth "$ex" --size 8 8 1 --connect 1 --labels l.txt -o missing/r.glb
[ "$(cat l.txt)" = "old labels" ] || fail "--labels was replaced although -o failed"
mkdir busy.png
expect 1 "error\[E745\]: cannot replace 'busy.png': Is a directory" -- \
  "$fgsg" synth "$ex" --size 8 8 1 --connect 1 --labels l.txt -o r.glb --preview busy.png
[ "$(cat l.txt)" = "old labels" ] || fail "--labels was replaced although --preview failed"
[ ! -e r.glb ] || fail "-o was written although --preview failed"
! ls -a | grep -q '\.tmp\.' || fail "temporaries left: $(ls -a)"

timeout 60 "$fgsg" synth "$ex" --size 8 8 1 --connect 1 --labels l.txt -o r.glb 2>err || { cat err >&2; fail "synth failed"; }
[ "$(cat l.txt)" != "old labels" ] || fail "--labels was not written"
[ "$(head -c 4 r.glb)" = "glTF" ] || fail "r.glb was not written"
! ls -a | grep -q '\.tmp\.' || fail "temporaries left: $(ls -a)"
exit 0

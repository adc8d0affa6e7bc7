#!/usr/bin/env bash
# fgsg run's outputs are one transaction: when --instances or --preview cannot be
# written, the old -o file is kept, and no temporary file is left anywhere.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
cd "$tmp" || fail "no scratch folder"
g="$inputs/outputs_spheres.fgsg"

no_temps() { ! ls -a "$@" 2>/dev/null | grep -q '\.tmp\.' || fail "a temporary file was left: $(ls -a "$@")"; }

echo "old mesh" > out.glb
echo "old json" > out.json
# A folder where the instances should go (root may write anywhere: no permission tricks).
mkdir busy.json
expect 1 "cannot replace 'busy.json': Is a directory" -- "$fgsg" run "$g" -q -o out.glb --instances busy.json
[ "$(cat out.glb)" = "old mesh" ] || fail "-o was replaced although --instances failed"
expect 1 "cannot write 'missing/i.json': No such file" -- "$fgsg" run "$g" -q -o out.glb --instances missing/i.json
[ "$(cat out.glb)" = "old mesh" ] || fail "-o was replaced although --instances failed"
expect 1 "cannot write 'missing/p.png'" -- "$fgsg" run "$g" -q -o out.glb --instances out.json --preview missing/p.png
[ "$(cat out.glb)" = "old mesh" ] || fail "-o was replaced although --preview failed"
[ "$(cat out.json)" = "old json" ] || fail "--instances was replaced although --preview failed"
no_temps . missing busy.json

# All writable: all three replaced.
expect 0 "wrote out.glb" -- "$fgsg" run "$g" -o out.glb --instances out.json --preview out.png
[ "$(head -c 4 out.glb)" = "glTF" ] || fail "out.glb was not written"
grep -q '"fgsg-instances"' out.json || fail "out.json was not written"
[ "$(head -c 4 out.png | tail -c 3)" = "PNG" ] || fail "out.png was not written"
no_temps .
exit 0

#!/usr/bin/env bash
# Temporaries left by killed runs (SIGKILL: nothing of fgsg runs to remove them) are
# removed by the next write to the same output; a temporary some process still holds
# locked, or one that is not ours by name, owner or kind, stays.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
succeeds() { timeout 60 "$@" >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "'$*' failed"; }; }
cd "$tmp" || fail "no scratch folder"
g="$inputs/outputs_spheres.fgsg"

# Killed while its output is staged (the preview renders after the mesh is written): the
# temporary stays behind.
echo "old" > big.glb
"$fgsg" run "$g" -q -o big.glb --instances big.json --preview big.png 2>/dev/null &
pid=$!
seen=0
for _ in $(seq 1 3000); do
  # Written, not just created (an empty young temporary may be one not yet locked).
  if [ -n "$(find . -maxdepth 1 -name 'big.glb.tmp.*' -size +0)" ]; then seen=1; break; fi
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.01
done
[ "$seen" -eq 1 ] || { wait "$pid"; fail "never saw the staged temporary (the run ended first)"; }
kill -KILL "$pid"
wait "$pid" 2>/dev/null
left=$(ls -a | grep '^big\.glb\.tmp\.' | head -1)
[ -n "$left" ] || fail "SIGKILL left no temporary (nothing to test)"
[ "$(cat big.glb)" = "old" ] || fail "big.glb was replaced by a killed run"

# Beside it: a stale one of ours written earlier (1 MB), one a live process holds locked,
# an empty one just created (its writer may not have locked it yet), a link and a file
# named otherwise, none of which may go.
head -c 1000000 /dev/zero > big.glb.tmp.Stale123
: > big.glb.tmp.Fresh123
ln -s big.json big.glb.tmp.Link1234
echo keep > big.glb.tmp.short
echo keep > other.glb.tmp.Other123
head -c 1000 /dev/zero > big.glb.tmp.Locked12
exec 9<big.glb.tmp.Locked12  # this shell holds it locked, as a live fgsg holds its own
flock -n 9 || fail "cannot lock a file here"

succeeds "$fgsg" run "$g" -q -o big.glb
exec 9<&-
[ ! -e "$left" ] || fail "the killed run's temporary $left is still there"
[ ! -e big.glb.tmp.Stale123 ] || fail "the stale temporary is still there"
for kept in big.glb.tmp.Locked12 big.glb.tmp.Fresh123 big.glb.tmp.short other.glb.tmp.Other123; do
  [ -e "$kept" ] || fail "$kept was removed"
done
[ -L big.glb.tmp.Link1234 ] || fail "the link was removed"
head -c 7 big.glb | grep -q "glTF" || fail "big.glb was not written"
exit 0

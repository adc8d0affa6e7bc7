#!/usr/bin/env bash
# Temporary outputs: a link planted at the old predictable name PATH.tmp.<pid> is never
# written through; a run stopped by SIGTERM or SIGINT leaves no temporary behind.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
cd "$tmp" || fail "no scratch folder"
g="$inputs/outputs_spheres.fgsg"

# The shell's pid becomes fgsg's through exec: the link sits at exactly the name
# the old writer would have opened (with O_TRUNC, following the link).
echo "precious" > victim
timeout 60 bash -c 'ln -s "$0/victim" "out.obj.tmp.$$" && exec "$1" run "$2" -q -o out.obj' "$tmp" "$fgsg" "$g" 2>err \
  || { cat err >&2; fail "the run failed with a link planted at its old temp name"; }
[ "$(cat victim)" = "precious" ] || fail "the planted link's target was overwritten"
head -c 7 out.obj | grep -q "# fgsg" || fail "out.obj was not written"
[ "$(ls -a | grep -c '\.tmp\.')" -eq 1 ] || fail "temporaries left: $(ls -a)"
rm -f out.obj.tmp.*

# Stopped while its outputs are staged (the preview renders after the mesh is staged):
# the signal removes the temporaries and still ends the process as a signal does.
for sig in TERM INT; do
  echo "old" > big.glb
  # A background job of a script starts with SIGINT ignored (and fgsg then leaves it
  # so): give it the default action, as a terminal's foreground job has.
  env --default-signal=INT "$fgsg" run "$g" -q -o big.glb --instances big.json --preview big.png 2>/dev/null &
  pid=$!
  seen=0
  for _ in $(seq 1 3000); do
    if ls -a | grep -q '^big\.glb\.tmp\.'; then seen=1; break; fi
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
  done
  [ "$seen" -eq 1 ] || { wait "$pid"; fail "SIG$sig: never saw the staged temporary (the run ended first)"; }
  kill -"$sig" "$pid"
  wait "$pid"
  status=$?
  want=$((128 + $(kill -l "$sig")))
  [ "$status" -eq "$want" ] || fail "SIG$sig: exit status $status, expected $want"
  [ "$(cat big.glb)" = "old" ] || fail "SIG$sig: big.glb was replaced by a stopped run"
  ! ls -a | grep -q '\.tmp\.' || fail "SIG$sig: temporaries left: $(ls -a)"
  [ ! -e big.json ] && [ ! -e big.png ] || fail "SIG$sig: a stopped run committed some outputs"
done
exit 0

#!/usr/bin/env bash
# The progress line: on a terminal, work over a second shows "fgsg run: deriving N s"
# (and is erased); piped, stderr holds the messages only. The terminal is util-linux's
# script(1) pseudo-terminal. usage: progress_line.sh FGSG SOURCE_DIR
set -u
fgsg="$1" source="$2"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
fail=0
grammar="$source/examples/fig17_collision_only.fgsg"  # about 2 s here: the genus-7 surface, then the pattern
export FGSG_PROGRESS_DELAY=0.3  # a faster machine still shows it
script -q -e -c "'$fgsg' run '$grammar' -o '$out/a.glb'" /dev/null > "$out/tty.txt" 2>&1 </dev/null
code=$?
if [ $code -ne 0 ] || ! grep -q "fgsg run: deriving [0-9.]* s" "$out/tty.txt" || ! grep -q "wrote $out/a.glb" "$out/tty.txt"; then
  echo "FAIL: on a terminal (exit $code) no progress line or no result line:"; cat -v "$out/tty.txt"; fail=1
fi
"$fgsg" run "$grammar" -o "$out/b.glb" 2> "$out/piped.txt" </dev/null
if grep -q "deriving" "$out/piped.txt" || grep -q $'\r' "$out/piped.txt"; then
  echo "FAIL: piped stderr carries the progress line:"; cat -v "$out/piped.txt"; fail=1
fi
script -q -e -c "'$fgsg' run '$grammar' -o '$out/c.glb' --quiet" /dev/null > "$out/quiet.txt" 2>&1 </dev/null
if grep -q "deriving" "$out/quiet.txt"; then
  echo "FAIL: --quiet printed the progress line:"; cat -v "$out/quiet.txt"; fail=1
fi
exit $fail

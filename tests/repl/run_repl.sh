#!/usr/bin/env bash
# Runs one REPL script tests/repl/<name>.script through `fgsg repl` (stdin not a terminal)
# in a scratch folder and compares stdout+stderr, then "exit N", with <name>.expected.
# When <name>.pre.sh exists it runs first in that folder. When <name>.post.sh exists it runs next in the same folder (with $FGSG set) and its
# output is appended before the comparison (e.g. `fgsg run` of a file the script saved).
set -uo pipefail
fgsg=$1
script=$2
dir=$(cd "$(dirname "$script")" && pwd)
name=$(basename "$script" .script)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
# <name>.pre.sh prepares the scratch folder (files the script reads).
if [ -f "$dir/$name.pre.sh" ]; then bash "$dir/$name.pre.sh" || exit 1; fi
"$fgsg" repl < "$dir/$name.script" > out.txt 2>&1
echo "exit $?" >> out.txt
if [ -f "$dir/$name.post.sh" ]; then
  FGSG=$fgsg bash "$dir/$name.post.sh" >> out.txt 2>&1
fi
if ! diff -u "$dir/$name.expected" out.txt; then
  echo "FAIL [repl: $name]: output differs" >&2
  exit 1
fi
echo "ok: repl $name"

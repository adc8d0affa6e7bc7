#!/usr/bin/env bash
# fgsg compile's usage errors (exit 2) and failures (exit 1): each with its message
# and without leaving files behind.
#   usage: compile_usage.sh FGSG SOURCE_ROOT
set -uo pipefail
fgsg=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL [compile_usage]: $*" >&2; exit 1; }
grammar=$root/examples/koch.fgsg

# expect CODE MESSAGE ARGS...: fgsg compile ARGS exits CODE and prints MESSAGE.
expect() {
  local code=$1 message=$2
  shift 2
  (cd "$tmp/out" && "$fgsg" compile "$@") >"$tmp/stdout" 2>"$tmp/stderr"
  local rc=$?
  [ $rc -eq "$code" ] || { cat "$tmp/stderr" >&2; fail "fgsg compile $*: exit $rc, expected $code"; }
  grep -qF -- "$message" "$tmp/stderr" || { cat "$tmp/stderr" >&2; fail "fgsg compile $*: no '$message'"; }
  [ -z "$(ls -A "$tmp/out")" ] || { ls -A "$tmp/out" >&2; fail "fgsg compile $*: left files behind"; }
}
mkdir -p "$tmp/out"
expect 2 "does not end in .so" "$grammar" -o koch.dylib
expect 2 "does not end in .so" "$grammar" -o libkoch.so.1
expect 2 "does not start with a letter" "$grammar" -o lib3d.so
expect 2 "characters other than" "$grammar" -o "lib koch.so"
expect 2 "names no library" "$grammar" -o lib.so
expect 2 "no grammar file given" -o libkoch.so
expect 2 "unknown option '--fast'" "$grammar" --fast
expect 2 "-o needs a value" "$grammar" -o
expect 2 "more than one grammar file" "$grammar" "$grammar"
expect 1 "no-such.fgsg" "$tmp/no-such.fgsg" -o libx.so
expect 1 "error" "$root/tests/cases/error_syntax/input.fgsg" -o libx.so
FGSG_LIBDIR=$tmp/nowhere expect 1 "libfgsg.so is not in" "$grammar" -o libkoch.so
expect 1 "does not exist" "$grammar" -o "$tmp/no/dir/libkoch.so"

# The linker's failure, with its output, and nothing left where the library would go.
printf '#!/bin/sh\necho "the linker says no" >&2\nexit 3\n' >"$tmp/badcc"
chmod +x "$tmp/badcc"
FGSG_CC=$tmp/badcc expect 1 "the linker says no" "$grammar" -o libkoch.so
FGSG_CC=$tmp/badcc expect 1 "exited with status 3" "$grammar" -o libkoch.so
FGSG_CC=$tmp/no-such-cc expect 1 "cannot run the C compiler" "$grammar" -o libkoch.so

# Defaults: lib + the grammar's stem + .so and the header beside it; --header elsewhere.
(cd "$tmp/out" && "$fgsg" compile "$grammar") 2>"$tmp/stderr" || { cat "$tmp/stderr" >&2; fail "default -o"; }
[ -f "$tmp/out/libkoch.so" ] && [ -f "$tmp/out/koch.h" ] || fail "no libkoch.so and koch.h in the current folder"
grep -qF "wrote libkoch.so and koch.h" "$tmp/stderr" || { cat "$tmp/stderr" >&2; fail "no 'wrote' line"; }
mkdir -p "$tmp/inc"
(cd "$tmp/out" && "$fgsg" compile "$grammar" -o "libkoch-v2.so" --header "$tmp/inc" --quiet) 2>"$tmp/stderr" ||
  { cat "$tmp/stderr" >&2; fail "--header"; }
[ -s "$tmp/stderr" ] && { cat "$tmp/stderr" >&2; fail "--quiet printed something"; }
[ -f "$tmp/out/libkoch-v2.so" ] && [ -f "$tmp/inc/koch_v2.h" ] || fail "no libkoch-v2.so and inc/koch_v2.h"
grep -q 'fgsg_program_koch_v2;' "$tmp/inc/koch_v2.h" || fail "koch_v2.h does not declare fgsg_program_koch_v2"
nm -D --defined-only "$tmp/out/libkoch-v2.so" | grep -qw fgsg_program_koch_v2 || fail "fgsg_program_koch_v2 is not exported"
echo "ok: compile_usage"

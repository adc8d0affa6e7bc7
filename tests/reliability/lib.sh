#!/usr/bin/env bash
# Shared by the reliability and CLI scripts: run a command under a time limit and check
# how it ended. Sourced as `. "$(dirname "$0")/lib.sh"` (tests/cli:
# `. "$(dirname "$0")/../reliability/lib.sh"`); the script's arguments are FGSG SOURCE_DIR.
set -uo pipefail
fgsg=${1:?fgsg binary}
root=${2:?source dir}
inputs="$root/tests/reliability/inputs"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
test_name=$(basename "$0" .sh)
fail() { echo "FAIL [$test_name]: $*" >&2; exit 1; }

# expect CODE PATTERN -- COMMAND...: COMMAND ends (within 60 s) with exit code CODE and
# its stderr matches the extended regex PATTERN; its stderr is left in $tmp/err.
expect() {
  local code=$1 pattern=$2
  shift 3
  timeout 60 "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  [ "$got" -eq "$code" ] || { cat "$tmp/err" >&2; fail "'$*': exit $got, expected $code"; }
  grep -qE -- "$pattern" "$tmp/err" || { cat "$tmp/err" >&2; fail "'$*': no message matching '$pattern'"; }
}

# same_message COMMAND...: three runs print the same stderr (no uninitialised reads).
same_message() {
  timeout 60 "$@" >/dev/null 2>"$tmp/m1"; timeout 60 "$@" >/dev/null 2>"$tmp/m2"
  cmp -s "$tmp/m1" "$tmp/m2" || fail "'$*' prints other messages on each run"
}

# watchdog SECONDS: a hang watchdog's budget, five times longer in the sanitized build
# (2-4x slower, and sanitized suites run beside other work), so that there it still
# catches a hang but not a slow process (deep_recursion's REPL took over 60 s at load 10).
watchdog() {
  if grep -qa __asan_init "$fgsg"; then echo $(($1 * 5)); else echo "$1"; fi
}

# skip_under_asan WHY: a test of elapsed time or of an address-space limit measures what
# AddressSanitizer changes (2-4x slower, terabytes of shadow reserved): it stops here in
# scripts/sanitize.sh's build, with 77, which CTest reports as skipped (SKIP_RETURN_CODE),
# and runs in every other.
skip_under_asan() {
  if grep -qa __asan_init "$fgsg"; then
    echo "$test_name: skipped under AddressSanitizer ($*)"
    exit 77
  fi
}

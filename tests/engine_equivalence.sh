#!/usr/bin/env bash
# The three engines agree byte for byte: derives one example (every `//   fgsg run
# examples/NAME.fgsg ...` header line, from the repository root) or one golden case
# folder (its args, inside the folder) with the interpreter, with the JIT, and through
# the grammar compiled to a shared library (fgsg compile + tests/tools/run_library),
# and compares the written .glb files. A case that must fail (a case folder with
# expected_errors.txt) must fail alike: same exit code, same diagnostics from both fgsg
# engines. Any other run must succeed: two engines failing alike is no agreement (#51).
#   engine_equivalence.sh FGSG RUN_LIBRARY ROOT (examples/NAME.fgsg | tests/cases/NAME)
set -uo pipefail
fgsg=$1
runlib=$2
root=$3
target=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export FGSG_CACHE_DIR="$tmp/cache"  # the JIT compiles each grammar afresh, then reuses it
name=$(basename "$target" .fgsg)
fail() { echo "FAIL [$name]: $*" >&2; exit 1; }
expect_error=false  # set for a case folder whose expected_errors.txt declares the failure

# Runs one grammar with the given options in the current folder, three ways.
compare() {
  local grammar=$1 tag=$2
  shift 2
  local rc_i rc_j
  # The flattened mesh, as the compiled library writes it (its C API has no scene).
  local flat=(--instancing off --group-by none)
  "$fgsg" run "$grammar" --engine=interp -q -o "$tmp/$tag-interp.glb" "${flat[@]}" "$@" 2>"$tmp/$tag-interp.err"
  rc_i=$?
  "$fgsg" run "$grammar" --engine=jit -q -o "$tmp/$tag-jit.glb" "${flat[@]}" "$@" 2>"$tmp/$tag-jit.err"
  rc_j=$?
  [ $rc_i -eq $rc_j ] || fail "$tag: exit codes differ (interp $rc_i, jit $rc_j)"
  cmp -s "$tmp/$tag-interp.err" "$tmp/$tag-jit.err" || {
    diff "$tmp/$tag-interp.err" "$tmp/$tag-jit.err" >&2
    fail "$tag: the engines report differently"
  }
  if [ $rc_i -ne 0 ]; then  # a failing run writes nothing to compare
    $expect_error && return 0
    cat "$tmp/$tag-interp.err" >&2
    fail "$tag: both engines failed alike (exit $rc_i), and no expected_errors.txt declares it"
  fi
  $expect_error && fail "$tag: expected_errors.txt declares an error, but both engines succeeded"
  cmp "$tmp/$tag-interp.glb" "$tmp/$tag-jit.glb" || fail "$tag: the JIT's output differs from the interpreter's"
  local lib="$tmp/lib${tag//-/_}.so"
  "$fgsg" compile "$grammar" -o "$lib" -q 2>"$tmp/$tag-compile.err" || {
    cat "$tmp/$tag-compile.err" >&2
    fail "$tag: fgsg compile failed"
  }
  "$runlib" "$lib" -o "$tmp/$tag-lib.glb" --quiet "$@" 2>"$tmp/$tag-lib.err" || {
    cat "$tmp/$tag-lib.err" >&2
    fail "$tag: the compiled library failed"
  }
  cmp "$tmp/$tag-interp.glb" "$tmp/$tag-lib.glb" || fail "$tag: the compiled library's output differs"
}

if [ -d "$target" ]; then
  cd "$target" || fail "no case folder"
  args=()
  [ -f args ] && read -r -a args < args
  if [ -f expected_errors.txt ] && [ "$(cat mode 2>/dev/null)" != run ]; then
    echo "ok: $name (a compile-time error case: no engine runs)"
    exit 0
  fi
  [ -f expected_errors.txt ] && expect_error=true
  compare input.fgsg case "${args[@]}"
  echo "ok: $name"
  exit 0
fi

cd "$root" || fail "no repository root"
runs=0
while IFS= read -r line; do
  read -r -a args <<< "$line"
  clean=()
  skip=0
  for a in "${args[@]}"; do
    if [ $skip = 1 ]; then skip=0; continue; fi
    # Files of their own and printed figures are not part of what is compared.
    case "$a" in --preview | --instances) skip=1 ;; --preview=* | --instances=* | --stats) ;; *) clean+=("$a") ;; esac
  done
  runs=$((runs + 1))
  compare "$target" "run$runs" "${clean[@]}"
done < <(grep -E '^//[[:space:]]+fgsg run examples/' "$target" | sed -E 's#^//[[:space:]]+fgsg run examples/[^ ]+##')
[ $runs -gt 0 ] || fail "no run line in the header"
echo "ok: $name ($runs runs)"

#!/usr/bin/env bash
# Runs one golden case folder tests/cases/<name>/:
#   input.fgsg            the grammar
#   args                  extra options for `fgsg run` (optional)
#   expected_stats.txt    `fgsg run --stats` output without its time.* lines (exact)
#   expected_ir.txt       `fgsg ir` output (exact, optional)
#   expected_geometry.txt the run's mesh as scripts/mesh_digest.py digests it: positions
#                         to its stated precision, triangles listed (or, for large ones,
#                         summarised and hashed); a change prints the first differences.
#                         Re-bless with scripts/bless_goldens.sh (docs/testing.md)
#   expected_errors.txt   an error case: `fgsg check` (or `fgsg run` when the file
#                         `mode` says run) must exit 1 and print every line given here
# A run case is also derived twice: the two .glb files must be byte-identical.
set -uo pipefail
fgsg=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL [$(basename "$dir")]: $*" >&2; exit 1; }
digest="$(cd "$(dirname "$0")/.." && pwd)/scripts/mesh_digest.py"

args=()
[ -f "$dir/args" ] && read -r -a args < "$dir/args"
# Run inside the case folder so printed file names read `input.fgsg`.
cd "$dir" || fail "no such case folder"

if [ -f "$dir/expected_errors.txt" ]; then
  mode=check
  [ -f "$dir/mode" ] && mode=$(cat "$dir/mode")
  if [ "$mode" = run ]; then
    "$fgsg" run input.fgsg -o "$tmp/out.glb" "${args[@]}" >"$tmp/stdout" 2>"$tmp/stderr"
  else
    "$fgsg" check input.fgsg >"$tmp/stdout" 2>"$tmp/stderr"
  fi
  rc=$?
  [ $rc -eq 1 ] || { cat "$tmp/stderr" >&2; fail "expected exit code 1, got $rc"; }
  while IFS= read -r line; do
    [ -z "$line" ] && continue
    grep -qF -- "$line" "$tmp/stderr" || { cat "$tmp/stderr" >&2; fail "missing in the diagnostics: $line"; }
  done < "$dir/expected_errors.txt"
  # A located error shows its source line with a caret under the column.
  if grep -qE '^input\.fgsg:[0-9]+:[0-9]+:' "$dir/expected_errors.txt"; then
    grep -q '\^' "$tmp/stderr" || fail "no caret line in the diagnostics"
  fi
  [ -f "$tmp/out.glb" ] && fail "an output file was written although the run failed"
  echo "ok: $(basename "$dir") (errors as expected)"
  exit 0
fi

"$fgsg" run input.fgsg -o "$tmp/a.glb" --stats --quiet "${args[@]}" >"$tmp/stats" 2>"$tmp/stderr" \
  || { cat "$tmp/stderr" >&2; fail "fgsg run failed"; }
grep -v '^time\.' "$tmp/stats" > "$tmp/stats.cut"
if [ -f "$dir/expected_stats.txt" ]; then
  diff -u "$dir/expected_stats.txt" "$tmp/stats.cut" >&2 || fail "statistics differ"
fi
if [ -f "$dir/expected_ir.txt" ]; then
  "$fgsg" ir input.fgsg > "$tmp/ir.txt" 2>"$tmp/stderr" || fail "fgsg ir failed"
  diff -u "$dir/expected_ir.txt" "$tmp/ir.txt" >&2 || fail "IR differs"
fi
if [ -f "$dir/expected_geometry.txt" ]; then
  "$fgsg" run input.fgsg -o "$tmp/geometry.obj" --quiet "${args[@]}" 2>"$tmp/stderr" || fail "the OBJ run failed"
  python3 "$digest" check "$dir/expected_geometry.txt" "$tmp/geometry.obj" || fail "geometry differs"
fi
"$fgsg" run input.fgsg -o "$tmp/b.glb" --quiet "${args[@]}" 2>"$tmp/stderr" || fail "second run failed"
cmp -s "$tmp/a.glb" "$tmp/b.glb" || fail "two runs with the same seed gave different .glb bytes"
echo "ok: $(basename "$dir")"

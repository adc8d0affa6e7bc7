#!/usr/bin/env bash
# Every standard-library module (stdlib/**/*.fgsg): it checks without warnings, runs alone
# with the same bytes in both engines and the golden output of stdlib_golden.txt (counts and
# the .obj's hash), and
# imports cleanly `as` a name (its unused rules and its own start raise nothing).
#   usage: stdlib_modules.sh FGSG SOURCE_DIR
set -uo pipefail
fgsg=$1 root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export FGSG_CACHE_DIR="$tmp/cache"
golden="$root/tests/modules/stdlib_golden.txt"
fail=0
cd "$root" || exit 1
modules=$(find stdlib -name '*.fgsg' | sort)
[ -n "$modules" ] || { echo "FAIL: no modules in stdlib/"; exit 1; }
for m in $modules; do
  if ! "$fgsg" check "$m" >"$tmp/check" 2>&1 || grep -q ": warning" "$tmp/check"; then
    echo "FAIL: fgsg check $m:"; cat "$tmp/check"; fail=1; continue
  fi
  "$fgsg" run "$m" -o "$tmp/jit.obj" >"$tmp/jit.out" 2>&1 || { echo "FAIL: fgsg run $m"; cat "$tmp/jit.out"; fail=1; continue; }
  "$fgsg" run "$m" -o "$tmp/interp.obj" --engine interp -q 2>&1 || { echo "FAIL: fgsg run --engine interp $m"; fail=1; continue; }
  cmp -s "$tmp/jit.obj" "$tmp/interp.obj" || { echo "FAIL: $m: the JIT and the interpreter differ"; fail=1; }
  figures="$(sed -n 's/^wrote .* (\([0-9]*\) instances, \([0-9]*\) triangles)$/\1 \2/p' "$tmp/jit.out") $(sha256sum < "$tmp/jit.obj" | cut -c1-16)"
  expected=$(awk -v m="$m" '$1 == m { print $2, $3, $4 }' "$golden")
  [ "$figures" = "$expected" ] || { echo "FAIL: $m: '$figures' (instances triangles obj-sha256), golden '$expected'"; fail=1; }
  name=${m#stdlib/}
  printf 'import "std/%s" as m;\naxiom: S(1, 1, 1) I("cube");\n' "${name%.fgsg}" > "$tmp/importer.fgsg"
  if ! "$fgsg" check "$tmp/importer.fgsg" >"$tmp/import" 2>&1 || grep -q ": warning" "$tmp/import"; then
    echo "FAIL: importing $m:"; cat "$tmp/import"; fail=1
  fi
done
exit $fail

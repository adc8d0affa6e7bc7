#!/usr/bin/env bash
# Every standard-library module (stdlib/**/*.fgsg): it checks without warnings, runs alone
# with the same bytes in both engines and the golden output in tests/modules/golden/ (its
# instance count and scripts/mesh_digest.py's digest of the .obj: counts, bounding box,
# centroid, area and a hash of the canonical geometry, readable in review; a difference
# prints what changed; re-bless with scripts/bless_goldens.sh), and
# imports cleanly `as` a name (its unused rules and its own start raise nothing).
#   usage: stdlib_modules.sh FGSG SOURCE_DIR
set -uo pipefail
fgsg=$1 root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export FGSG_CACHE_DIR="$tmp/cache"
golden="$root/tests/modules/golden"
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
  expected="$golden/${m#stdlib/}.txt"
  { sed -n 's/^wrote .* (\([0-9]*\) instances, [0-9]* triangles)$/instances \1/p' "$tmp/jit.out"
    python3 "$root/scripts/mesh_digest.py" digest "$tmp/jit.obj" --full-limit 0; } >"$tmp/actual.txt"
  if [ ! -f "$expected" ]; then
    echo "FAIL: $m: no golden output $expected"; fail=1
  elif ! python3 "$root/scripts/mesh_digest.py" diff "$expected" "$tmp/actual.txt"; then
    echo "FAIL: $m: the output differs from $expected"; fail=1
  fi
  name=${m#stdlib/}
  printf 'import "std/%s" as m;\naxiom: S(1, 1, 1) I("cube");\n' "${name%.fgsg}" > "$tmp/importer.fgsg"
  if ! "$fgsg" check "$tmp/importer.fgsg" >"$tmp/import" 2>&1 || grep -q ": warning" "$tmp/import"; then
    echo "FAIL: importing $m:"; cat "$tmp/import"; fail=1
  fi
done
exit $fail

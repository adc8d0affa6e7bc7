#!/usr/bin/env bash
# Re-bless the golden geometry (#51) after a change that is meant to move it, then review
# the diff before committing (git diff tests/cases tests/modules/golden): every file is
# readable text — counts, bounding box, centroid, area, and the triangles themselves for
# small outputs — so what changed shows in review.
#   tests/cases/*/expected_geometry.txt   scripts/mesh_digest.py's digest of each run case
#   tests/modules/golden/**.fgsg.txt      each stdlib module run alone: instances + digest
# usage: scripts/bless_goldens.sh FGSG [CASE_OR_MODULE_NAME...]  (none: all of them)
set -euo pipefail
fgsg=$(realpath "${1:?usage: bless_goldens.sh FGSG [NAME...]}")
shift
root=$(cd "$(dirname "$0")/.." && pwd)
digest="$root/scripts/mesh_digest.py"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export FGSG_CACHE_DIR="$tmp/cache"
chosen() {  # chosen NAME: true when no names were given or NAME is one of them
  [ ${#names[@]} -eq 0 ] && return 0
  local n; for n in "${names[@]}"; do [ "$n" = "$1" ] && return 0; done; return 1
}
names=("$@")

for dir in "$root"/tests/cases/*/; do
  name=$(basename "$dir")
  [ -f "$dir/input.fgsg" ] && [ ! -f "$dir/expected_errors.txt" ] && chosen "$name" || continue
  args=()
  [ -f "$dir/args" ] && read -r -a args < "$dir/args"
  (cd "$dir" && "$fgsg" run input.fgsg -o "$tmp/case.obj" --quiet "${args[@]}")
  python3 "$digest" digest "$tmp/case.obj" > "$tmp/digest.txt"
  mv "$tmp/digest.txt" "$dir/expected_geometry.txt"
  echo "blessed tests/cases/$name/expected_geometry.txt"
done

cd "$root"
for m in $(find stdlib -name '*.fgsg' | sort); do
  chosen "$m" || continue
  out="tests/modules/golden/${m#stdlib/}.txt"
  mkdir -p "$(dirname "$out")"
  "$fgsg" run "$m" -o "$tmp/module.obj" > "$tmp/run.out" 2>&1
  { sed -n 's/^wrote .* (\([0-9]*\) instances, [0-9]* triangles)$/instances \1/p' "$tmp/run.out"
    python3 "$digest" digest "$tmp/module.obj" --full-limit 0; } > "$tmp/golden.txt"
  mv "$tmp/golden.txt" "$out"
  echo "blessed $out"
done

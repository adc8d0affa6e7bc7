#!/usr/bin/env bash
# Runs one example as its header says (every `//   fgsg run examples/NAME.fgsg ...`
# line), writing into a temporary folder; each .glb must pass the official glTF
# validator and each preview must be a PNG.
set -uo pipefail
fgsg=$1
example=$2
root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
name=$(basename "$example" .fgsg)
fail() { echo "FAIL [$name]: $*" >&2; exit 1; }

# Every header line runs (an example may show itself on several surfaces), from the
# repository root so that paths such as tests/data/meshes/bunny00.off resolve.
cd "$root" || fail "no repository root $root"
validator="$root/scripts/validate-gltf.js"
[ -d "$root/tools/node/node_modules/gltf-validator" ] || fail "gltf-validator is not installed: run scripts/install-deps.sh"
runs=0
while IFS= read -r line; do
  read -r -a args <<< "$line"
  # Drop the example's own --preview target; the test names its own files.
  clean=()
  skip=0
  for a in "${args[@]}"; do
    if [ $skip = 1 ]; then skip=0; continue; fi
    case "$a" in --preview) skip=1 ;; --preview=*) ;; *) clean+=("$a") ;; esac
  done
  runs=$((runs + 1))
  out="$tmp/$name-$runs"
  "$fgsg" run "$example" -o "$out.glb" --preview "$out.png" --instances "$out.json" \
    "${clean[@]}" 2>"$tmp/stderr" || { cat "$tmp/stderr" >&2; fail "fgsg run failed: ${args[*]}"; }
  [ -s "$out.glb" ] || fail "no .glb written: ${args[*]}"
  head -c 8 "$out.png" | od -An -c | grep -q 'P   N   G' || fail "the preview is not a PNG"
  node "$validator" "$out.glb" >"$tmp/validator" 2>&1 || { cat "$tmp/validator" >&2; fail "gltf-validator reported errors"; }
done < <(grep -E '^//[[:space:]]+fgsg run examples/' "$example" | sed -E 's#^//[[:space:]]+fgsg run examples/[^ ]+##')
[ $runs -gt 0 ] || fail "no '//   fgsg run examples/$name.fgsg ...' line in the header"
echo "ok: $name ($runs runs)"

#!/usr/bin/env bash
# Runs one example as its header says (the first `//   fgsg run examples/NAME.fgsg ...`
# line), writing into a temporary folder; the .glb must pass the official glTF
# validator and the preview must be a PNG.
set -uo pipefail
fgsg=$1
example=$2
root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
name=$(basename "$example" .fgsg)
fail() { echo "FAIL [$name]: $*" >&2; exit 1; }

line=$(grep -m1 -E '^//[[:space:]]+fgsg run examples/' "$example" | sed -E 's#^//[[:space:]]+fgsg run examples/[^ ]+##')
read -r -a args <<< "$line"
# Drop the example's own --preview target; the test names its own files.
clean=()
skip=0
for a in "${args[@]}"; do
  if [ $skip = 1 ]; then skip=0; continue; fi
  case "$a" in --preview) skip=1 ;; --preview=*) ;; *) clean+=("$a") ;; esac
done
"$fgsg" run "$example" -o "$tmp/$name.glb" --preview "$tmp/$name.png" --instances "$tmp/$name.json" \
  "${clean[@]}" 2>"$tmp/stderr" || { cat "$tmp/stderr" >&2; fail "fgsg run failed"; }
[ -s "$tmp/$name.glb" ] || fail "no .glb written"
head -c 8 "$tmp/$name.png" | od -An -c | grep -q 'P   N   G' || fail "the preview is not a PNG"
validator="$root/scripts/validate-gltf.js"
[ -d "$root/tools/node/node_modules/gltf-validator" ] || fail "gltf-validator is not installed: run scripts/install-deps.sh"
node "$validator" "$tmp/$name.glb" >"$tmp/validator" 2>&1 || { cat "$tmp/validator" >&2; fail "gltf-validator reported errors"; }
echo "ok: $name"

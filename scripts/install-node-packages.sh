#!/usr/bin/env bash
# Installs the npm packages fgsg uses into tools/node/, pinned: the Khronos glTF
# validator (the tests check every .glb we write against it), three.js (the page of
# `fgsg view`, served from the build folder), playwright-core (drives Debian's chromium
# in the viewer's browser tests), vscode-jsonrpc (the LSP client that drives `fgsg lsp`
# in its tests) and vscode-textmate with vscode-oniguruma (VS Code's tokeniser, which
# the tests run on editors/*.tmLanguage.json). Idempotent: when the pinned versions are
# already installed nothing touches the network, so a second run works offline.
set -euo pipefail

# Only 2.0.0-dev.* releases of the validator exist; a range like @2 would not match one.
packages=("gltf-validator@2.0.0-dev.3.10" "three@0.187.0" "playwright-core@1.65.2" "vscode-jsonrpc@10.0.0"
          "vscode-textmate@9.4.0" "vscode-oniguruma@2.0.1")
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
prefix="$root/tools/node"

if ! command -v npm >/dev/null 2>&1; then
  echo "fgsg: npm not found; install nodejs and npm (apt-get install nodejs npm)" >&2
  exit 1
fi

missing=()
for spec in "${packages[@]}"; do
  name="${spec%@*}" version="${spec##*@}"
  pkg="$prefix/node_modules/$name/package.json"
  [ -f "$pkg" ] && grep -q "\"version\": *\"$version\"" "$pkg" || missing+=("$spec")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "fgsg: npm packages already in $prefix (${packages[*]})"
  exit 0
fi

mkdir -p "$prefix"
echo "fgsg: installing ${missing[*]} into $prefix"
if ! npm install --prefix "$prefix" --no-audit --no-fund --save-exact "${missing[@]}"; then
  echo "fgsg: npm could not install ${missing[*]} (offline? see the npm error above)" >&2
  exit 1
fi
node "$root/scripts/validate-gltf.js" --version

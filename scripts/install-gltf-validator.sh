#!/usr/bin/env bash
# Installs the Khronos glTF validator (npm package gltf-validator) into tools/node/ so the
# tests can check every .glb we write against the real validator. Idempotent: when the
# pinned version is already installed nothing touches the network, so a second run works
# offline.
set -euo pipefail

# Only 2.0.0-dev.* releases exist; a range like @2 would not match a prerelease.
version="2.0.0-dev.3.10"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
prefix="$root/tools/node"
pkg="$prefix/node_modules/gltf-validator/package.json"

if ! command -v npm >/dev/null 2>&1; then
  echo "fgsg: npm not found; install nodejs and npm (apt-get install nodejs npm)" >&2
  exit 1
fi

if [ -f "$pkg" ] && grep -q "\"version\": *\"$version\"" "$pkg"; then
  echo "fgsg: gltf-validator $version already in $prefix"
  exit 0
fi

mkdir -p "$prefix"
echo "fgsg: installing gltf-validator $version into $prefix"
if ! npm install --prefix "$prefix" --no-audit --no-fund --save-exact "gltf-validator@$version"; then
  echo "fgsg: npm could not install gltf-validator@$version (offline? see the npm error above)" >&2
  exit 1
fi
node "$root/scripts/validate-gltf.js" --version

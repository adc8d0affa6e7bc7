#!/usr/bin/env bash
# Copies real-world test meshes (and a few broken ones) from CGAL's data archive, shipped in
# the Debian package libcgal-demo, into tests/data/meshes/ (git-ignored; see
# tests/data/README.md). Idempotent and quiet: when every mesh is already there nothing
# touches the network, so a second run works offline. Needs no root: apt-get download
# only fetches the .deb (the package lists must exist, as after apt-get update).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dest="$root/tests/data/meshes"
package="libcgal-demo"
archive="./usr/share/doc/libcgal-dev/data.tar.gz"  # inside the .deb
meshes=(
  # sound surfaces
  bunny00.off armadillo.off elephant.off refined_elephant.off elephant-with-holes.off
  ChineseDragon-10kv.off double-torus-example.off sphere.ply sphere.stl
  # broken ones, each for one kind of problem
  degtri_sliding.off mpi.off cube-ouvert.off tet-shuffled.off polygon_mesh.off pig.stl
  b9.ply mesh_with_colors.off
)

missing=()
for m in "${meshes[@]}"; do
  [ -s "$dest/$m" ] || missing+=("$m")
done
[ ${#missing[@]} -eq 0 ] && exit 0

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# apt-get chatters (and warns when run as root); show it only when it fails.
if ! out="$(cd "$tmp" && apt-get download -q "$package" 2>&1)"; then
  echo "$out" >&2
  echo "fgsg: could not download $package (offline, or no package lists: run apt-get update)" >&2
  exit 1
fi
deb="$(ls "$tmp"/"$package"_*.deb)"

members=()
for m in "${missing[@]}"; do members+=("data/meshes/$m"); done
if ! dpkg-deb --fsys-tarfile "$deb" | tar -xO "$archive" | tar -xz -C "$tmp" "${members[@]}"; then
  echo "fgsg: $(basename "$deb") lacks some of: ${missing[*]} (another CGAL version?)" >&2
  exit 1
fi

mkdir -p "$dest"
for m in "${missing[@]}"; do
  # Copy then rename, so an interrupted run never leaves a half-written mesh behind.
  cp "$tmp/data/meshes/$m" "$dest/.$m.part"
  mv "$dest/.$m.part" "$dest/$m"
done

#!/usr/bin/env bash
# Unpacks the demo meshes of Debian's libcgal-demo (data/meshes/*.off: cow, camel,
# elephant, dino, armadillo, ...) into the folder given as argument, installing the
# package first if it is missing. Usage: unpack_demo_meshes.sh DEST_DIR
set -euo pipefail

dest=${1:?usage: unpack_demo_meshes.sh DEST_DIR}
archive=/usr/share/doc/libcgal-dev/data.tar.gz

if [ ! -f "$archive" ]; then
  bash "$(dirname "$0")/install_dependencies.sh"
fi
[ -f "$archive" ] || { echo "error: $archive not found (Debian package libcgal-demo)" >&2; exit 1; }

mkdir -p "$dest"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
tar -xzf "$archive" -C "$tmp" --wildcards 'data/meshes/*.off'
cp "$tmp"/data/meshes/*.off "$dest"/
echo "Demo meshes unpacked into $dest ($(ls "$dest"/*.off | wc -l) files)"

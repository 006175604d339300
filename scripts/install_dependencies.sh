#!/usr/bin/env bash
# Installs, with apt-get, the Debian packages that building, testing and documenting the
# package need (the Python module: python3-dev, pybind11-dev, and numpy, SciPy and pytest
# for its tests), skipping those already installed. Needs root (or sudo).
#
#   bash scripts/install_dependencies.sh [--with-blender]
set -euo pipefail

packages=(g++ cmake make ninja-build libcgal-dev libcgal-demo libboost-graph-dev libboost-test-dev
          libeigen3-dev nlohmann-json3-dev doxygen libassimp-dev libtinygltf-dev
          python3-dev pybind11-dev python3-numpy python3-scipy python3-pytest)
# --with-blender (the tests): Blender and the numpy its glTF importer needs, to import and
# pose the skinned glTF files that skeletonize writes.
if [ "${1:-}" = "--with-blender" ]; then
  packages+=(blender python3-numpy)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "error: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo=sudo
fi
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

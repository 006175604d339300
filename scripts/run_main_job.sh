#!/usr/bin/env bash
# Installs what is missing (apt-get), builds the package's main program in ./build and runs
# it on a default demo mesh (Debian's libcgal-demo cow.off), or on the mesh given as argument.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --parallel "$(nproc)" --target geodesic_distances_example
input=${1:-build/data/meshes/cow.off}
echo "== geodesic_distances_example $input"
build/examples/geodesic_distances_example "$input"

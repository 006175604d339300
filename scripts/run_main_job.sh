#!/usr/bin/env bash
# Installs what is missing (apt-get), builds the package's main program `skeletonize` in
# ./build and runs it on a default demo mesh (Debian's libcgal-demo cow.off), or on the mesh
# given as argument: writes build/<name>.json (the report and the skeletons) and
# build/<name>.svg (a picture of the mesh with its control skeleton).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --parallel "$(nproc)" --target skeletonize
input=${1:-build/data/meshes/cow.off}
name=$(basename "${input%.*}")
build/examples/skeletonize "$input" -o "build/$name.json" --svg "build/$name.svg"
echo "Wrote build/$name.json (JSON report: stages, timings, curve and control skeletons)"
echo "  and build/$name.svg (the mesh and its control skeleton in three views)."

#!/usr/bin/env bash
# Regenerates the pictures of the README and the manual (doc/figures/*.svg) with the
# package's own `skeletonize` program on Debian's demo meshes. Run from a configured build:
#   bash scripts/make_figures.sh [BUILD_DIR]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" --target skeletonize >/dev/null
mkdir -p doc/figures
for mesh in cow dino homer elephant; do
  "$build/examples/skeletonize" "$build/data/meshes/$mesh.off" -o "/tmp/$mesh.json" \
    --svg "doc/figures/$mesh.svg"
done
echo "Figures written to doc/figures/"

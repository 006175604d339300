#!/usr/bin/env bash
# Regenerates the pictures of the README and the manual (doc/figures/*.svg) with the
# package's own `skeletonize` program on Debian's demo meshes, and, when Blender is installed,
# the Blender add-on's picture (doc/figures/blender_addon_cow.png). Run from a configured build:
#   bash scripts/make_figures.sh [BUILD_DIR]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" --target skeletonize >/dev/null
mkdir -p doc/figures
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
meshes="$build/data/meshes"
# The stages on the cow (the paper's figures 3, 4 and 6), then control skeletons (figure 7).
for stage in thinned pruned reeb control; do
  "$build/examples/skeletonize" "$meshes/cow.off" -o "$tmp/out.json" --svg "doc/figures/cow_$stage.svg" --svg-stage "$stage"
done
# The cow cut by the bone of largest weight (the skinning's hard segmentation).
"$build/examples/skeletonize" "$meshes/cow.off" -o "$tmp/out.json" --svg doc/figures/cow_weights.svg --svg-stage weights
for mesh in dino homer elephant; do
  "$build/examples/skeletonize" "$meshes/$mesh.off" -o "$tmp/out.json" --svg "doc/figures/$mesh.svg"
done
# The cow rigged by the Blender add-on, rendered headless (scripts/make_addon_screenshot.py).
if command -v blender >/dev/null; then
  cmake --build "$build" --target blender_addon_zip >/dev/null
  BLENDER_USER_SCRIPTS="$tmp/blender" BLENDER_USER_CONFIG="$tmp/blender" \
    blender -b --factory-startup --python-exit-code 1 --python scripts/make_addon_screenshot.py -- \
    "$build/blender/geodesic_skeleton_rig.zip" "$meshes/cow.off" doc/figures/blender_addon_cow.png >/dev/null 2>&1
fi
echo "Figures written to doc/figures/"

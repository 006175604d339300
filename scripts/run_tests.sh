#!/usr/bin/env bash
# Installs what is missing (apt-get), builds the package's tests, examples and documentation
# checks in ./build, and runs them with CTest (Blender too, which a test imports the skinned
# glTF output into). Exits non-zero when any test fails.
# GEODESIC_SKELETON_JOBS=N sets the build and test jobs (default: the number of cores).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${GEODESIC_SKELETON_JOBS:-$(nproc)}"
bash scripts/install_dependencies.sh --with-blender
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$jobs"
cd build
ctest --output-on-failure --parallel "$jobs"

#!/usr/bin/env bash
# The README's test command (CI runs it). Installs what is missing (apt-get), then:
#  1. builds the programs as users build them (Release, in ./build): the examples, skeletonize,
#     the code that the README and the manual show, the installed package used from an outside
#     project, the documentation check, the Python module; and runs their tests with CTest
#     (the module's pytest suite among them; Blender too, which a test imports the skinned
#     glTF output and the module into);
#  2. builds the unit-test suites, the fuzz corpus replay and skeletonize with AddressSanitizer
#     and UndefinedBehaviorSanitizer, assertions on (scripts/run_sanitizer_tests.sh, in
#     ./build-sanitize), and runs them with skeletonize's tests.
# Each piece of code is compiled once per check. Exits non-zero when any test fails.
# GEODESIC_SKELETON_JOBS=N sets the build and test jobs (default: the number of cores).
# The benchmarks are built by the commands in benchmark/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${GEODESIC_SKELETON_JOBS:-$(nproc)}"
bash scripts/install_dependencies.sh --with-blender
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release \
  -DGEODESIC_SKELETON_BUILD_UNIT_TESTS=OFF -DGEODESIC_SKELETON_BUILD_BENCHMARKS=OFF \
  -DGEODESIC_SKELETON_BUILD_PYTHON=ON
cmake --build build --parallel "$jobs"
(cd build && ctest --output-on-failure --parallel "$jobs")
bash scripts/run_sanitizer_tests.sh

#!/usr/bin/env bash
# Builds the unit tests (geodesic_skeleton_tests), the fuzz corpus replay and skeletonize with
# AddressSanitizer and UndefinedBehaviorSanitizer in ./build-sanitize, and runs the unit-test
# suites, the fuzz corpus and the skeletonize tests with CTest (scripts/run_tests.sh runs
# this script after the optimised build; the unit suites run only here). Any sanitizer report ends the program with exit code 86
# (ASan, UBSan; no recovery) and so fails its test; this script exits non-zero then.
#
#   bash scripts/run_sanitizer_tests.sh            # GEODESIC_SKELETON_JOBS=N sets the build jobs
#
# Left out: the other examples (their code paths are the suites' own), the benchmarks,
# the doc check and the install test (it builds an outside project: no new code runs); the
# optimised build of scripts/run_tests.sh runs them.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
jobs="${GEODESIC_SKELETON_JOBS:-$(nproc)}"
build=build-sanitize

# UBSan's arithmetic checks (signed overflow, shifts, division by zero, array bounds, bool
# and enum values, missing returns, ...); not its checks of every member access and pointer
# step (null, alignment, pointer-overflow, object-size, vptr): on this template-heavy code
# they more than double the compile time (measured: one pipeline, 158 s against 71 s), and
# AddressSanitizer reports what they would catch that matters here (null and out-of-bounds
# accesses). SANITIZER_FLAGS="..." replaces the whole set, e.g. with "-g1" added for line numbers.
sanitize="${SANITIZER_FLAGS:--fsanitize=address,undefined -fno-sanitize=null,alignment,pointer-overflow,object-size,vptr -fno-sanitize-recover=all -fno-omit-frame-pointer}"
# -O1: fast enough for CGAL. No NDEBUG: the package's and CGAL's assertions stay on too.
# Ninja builds the three targets side by side (make would build them one after another).
if [ -f "$build/CMakeCache.txt" ]; then
  grep -q "^CMAKE_GENERATOR:INTERNAL=Ninja$" "$build/CMakeCache.txt" || rm -rf "$build" # this script's own folder
fi
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Sanitize \
  "-DCMAKE_CXX_FLAGS_SANITIZE=-O1 $sanitize" \
  "-DCMAKE_EXE_LINKER_FLAGS_SANITIZE=$sanitize" \
  -DGEODESIC_SKELETON_BUILD_BENCHMARKS=OFF -DGEODESIC_SKELETON_BUILD_DOC=OFF
cmake --build "$build" --parallel "$jobs" --target geodesic_skeleton_tests fuzz_skeletonize_replay skeletonize

# Every report is fatal and has its own exit code, which the expected-failure tests
# (examples/expect_failure.cmake) reject as well as the others.
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:exitcode=86:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:exitcode=86"
export LSAN_OPTIONS="exitcode=86"

# The unit-test suites (named as in test/CMakeLists.txt), the fuzz corpus and the skeletonize tests.
suites=$(sed -n '/^set(GEODESIC_SKELETON_TEST_SUITES/,/^)/{/^ /p}' test/CMakeLists.txt | tr -d ' ' | paste -sd'|')
cd "$build"
ctest --output-on-failure --parallel "$jobs" -R "^(${suites}|fuzz_corpus_replay|example_skeletonize.*|skeletonize_.*)\$"

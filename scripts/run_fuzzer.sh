#!/usr/bin/env bash
# Builds the libFuzzer harness fuzz/fuzz_skeletonize (clang, -fsanitize=fuzzer,address,
# undefined) in ./build-fuzz and runs it for a bounded time on the seed corpus
# (fuzz/corpus) and the regressions (fuzz/regressions). New inputs go to
# build-fuzz/corpus, crashing ones to build-fuzz/findings/. Exits non-zero on a finding.
#
#   bash scripts/run_fuzzer.sh [SECONDS]        # default 300; GEODESIC_SKELETON_JOBS=N build jobs
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-300}"
jobs="${GEODESIC_SKELETON_JOBS:-$(nproc)}"
build=build-fuzz

bash scripts/install_dependencies.sh
missing=()
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
cxx=$(command -v clang++-14 || command -v clang++)

cmake -S . -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Fuzz \
  "-DCMAKE_CXX_FLAGS_FUZZ=-O2 -g1" \
  -DGEODESIC_SKELETON_BUILD_FUZZERS=ON -DGEODESIC_SKELETON_BUILD_TESTS=OFF \
  -DGEODESIC_SKELETON_BUILD_EXAMPLES=OFF -DGEODESIC_SKELETON_BUILD_BENCHMARKS=OFF \
  -DGEODESIC_SKELETON_BUILD_DOC=OFF
cmake --build "$build" --parallel "$jobs" --target fuzz_skeletonize

mkdir -p "$build/corpus" "$build/findings"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# -timeout: a hang; -rss_limit_mb (and the malloc limit it sets): absurd allocations;
# -max_len: mesh files of a few kilobytes reach every stage at resolution 16.
"$build/fuzz/fuzz_skeletonize" \
  -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
  -dict=fuzz/mesh_formats.dict -artifact_prefix="$build/findings/" -print_final_stats=1 \
  "$build/corpus" fuzz/corpus fuzz/regressions

#!/usr/bin/env bash
# Builds and runs every test (build/, the plain RelWithDebInfo build scripts/run.sh uses). CI runs
# this. --sanitize runs the same tests under AddressSanitizer and UndefinedBehaviorSanitizer
# instead (build-sanitize/, -O1 -g1: all checks kept, reports keep file:line): the sanitized
# compile costs 1.8 times the plain one, and the two together no longer fit CI's 20 minutes on
# 2 cores, so the sanitizer run is done before each merge to main (docs/development.md, "Tests").
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh

# The benchmarks are built by scripts/bench.sh (Release), not here: tests only.
if [ "${1:-}" = "--sanitize" ]; then
  # File by file (no unity batches): this build also checks that every source compiles on its
  # own, which a batch can hide (a header included by a neighbour in the same batch).
  BUILD_DIR=build-sanitize BUILD_TYPE=RelWithDebInfo ./scripts/build.sh -DACCELCAL_SANITIZE=ON \
    -DACCELCAL_BUILD_BENCH=OFF -DACCELCAL_UNITY=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
  (cd build-sanitize && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j"$(nproc)")
else
  BUILD_DIR=build ./scripts/build.sh -DACCELCAL_BUILD_BENCH=OFF -DACCELCAL_UNITY=ON
  (cd build && ctest --output-on-failure -j"$(nproc)")
fi

#!/usr/bin/env bash
# Builds and runs every test under AddressSanitizer and UndefinedBehaviorSanitizer
# (build-sanitize/, -O1 -g1: the sanitizers keep all their checks, reports keep file:line, and the
# build compiles faster than at -O2). One build, all tests: a sanitized run checks everything a
# plain run checks, plus memory and undefined behaviour, and CI (2 cores, 20 minutes) cannot
# afford the whole tree compiled twice. --no-sanitize runs the same tests in the plain build
# (build/, the one scripts/run.sh uses) instead.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh

# The benchmarks are built by scripts/bench.sh (Release), not here: tests only.
if [ "${1:-}" = "--no-sanitize" ]; then
  BUILD_DIR=build ./scripts/build.sh -DACCELCAL_BUILD_BENCH=OFF
  (cd build && ctest --output-on-failure -j"$(nproc)")
else
  BUILD_DIR=build-sanitize BUILD_TYPE=RelWithDebInfo ./scripts/build.sh -DACCELCAL_SANITIZE=ON \
    -DACCELCAL_BUILD_BENCH=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
  (cd build-sanitize && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j"$(nproc)")
fi

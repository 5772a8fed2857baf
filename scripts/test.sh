#!/usr/bin/env bash
# Builds and runs every test: once in a normal build (build/), once under AddressSanitizer and
# UndefinedBehaviorSanitizer (build-sanitize/). Pass --no-sanitize to skip the second.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh

# The benchmarks are built by scripts/bench.sh (Release), not here: tests only.
BUILD_DIR=build ./scripts/build.sh -DACCELCAL_BUILD_BENCH=OFF
(cd build && ctest --output-on-failure -j"$(nproc)")

if [ "${1:-}" != "--no-sanitize" ]; then
  # Benchmarks are timing tools, not tests: leave them out of the sanitizer build.
  # -O1 -g1: the sanitizers keep all their checks and reports keep file:line, and this build,
  # the longest part of CI, compiles faster than at -O2 -g.
  BUILD_DIR=build-sanitize BUILD_TYPE=RelWithDebInfo ./scripts/build.sh -DACCELCAL_SANITIZE=ON \
    -DACCELCAL_BUILD_BENCH=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
  (cd build-sanitize && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j"$(nproc)")
fi

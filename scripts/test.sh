#!/usr/bin/env bash
# Builds and runs every test: once in a normal build (build/), once under AddressSanitizer and
# UndefinedBehaviorSanitizer (build-sanitize/). Pass --no-sanitize to skip the second.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh

BUILD_DIR=build ./scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)")

if [ "${1:-}" != "--no-sanitize" ]; then
  # Benchmarks are timing tools, not tests: leave them out of the sanitizer build.
  # -O2 -g: the sanitizers keep their checks and the simulation-heavy tests stay fast.
  BUILD_DIR=build-sanitize BUILD_TYPE=RelWithDebInfo ./scripts/build.sh -DACCELCAL_SANITIZE=ON -DACCELCAL_BUILD_BENCH=OFF
  (cd build-sanitize && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j"$(nproc)")
fi

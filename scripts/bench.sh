#!/usr/bin/env bash
# Builds in Release and runs the benchmarks (figures are recorded in bench/README.md).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=build-release BUILD_TYPE=Release ./scripts/build.sh
./build-release/bench/accelcal_bench "$@"

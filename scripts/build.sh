#!/usr/bin/env bash
# Configures and builds accelcal into build/ (or the directory in $BUILD_DIR). Extra arguments
# go to cmake's configure step; $BUILD_TARGETS limits the build to those targets (run.sh builds
# only the program). ccache is used when it is installed (not needed; it speeds up rebuilds).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-RelWithDebInfo}" "${launcher[@]}" "$@" >/dev/null
targets=()
for t in ${BUILD_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build_dir" -j"$(nproc)" "${targets[@]}"

#!/usr/bin/env bash
# Times a build from scratch of one revision: the program alone (what scripts/run.sh builds) and
# then everything the tests need, in a fresh clone, ccache off, at the flags that revision's
# scripts use. Prints CPU (user + sys) and wall seconds for each; CPU is the figure to compare on
# a shared machine (wall on 2 cores is at best CPU / 2).
# Usage: bench/build_time.sh [REVISION]   (default HEAD)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
rev=${1:-HEAD}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q "$repo" "$work/src"
git -C "$work/src" checkout -q "$rev"
export CCACHE_DISABLE=1
cd "$work/src"
# What the revision's scripts pass; the build type is RelWithDebInfo in both eras.
unity=()
grep -q ACCELCAL_UNITY CMakeLists.txt && unity=(-DACCELCAL_UNITY=ON)   # as run.sh and test.sh
cmake -S . -B "$work/b" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DACCELCAL_BUILD_BENCH=OFF "${unity[@]}" >/dev/null
timed() {  # $1: label, rest: the command
  local label=$1; shift
  /usr/bin/time -f "$label: %e s wall, %U s user, %S s sys" "$@" >/dev/null
}
timed "$(git rev-parse --short HEAD) program" cmake --build "$work/b" -j"$(nproc)" --target accelcal
timed "$(git rev-parse --short HEAD) rest of the test build" cmake --build "$work/b" -j"$(nproc)"

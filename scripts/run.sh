#!/usr/bin/env bash
# Installs what is missing, builds, and runs the calibration wizard on the virtual bench: full
# screen on a terminal, plain prompts otherwise. Extra arguments go to `accelcal wizard`
# (e.g. --speed 1 for real time, --session FILE to resume one, --plain).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh --no-test   # Chromium is for the tests only
# The program alone: the tests and benchmarks are for scripts/test.sh and scripts/bench.sh.
BUILD_TARGETS=accelcal ./scripts/build.sh -DACCELCAL_UNITY=ON   # batches: half the compile time
# --speed 20: the simulated bench runs 20 times faster than real time, so a whole session of
# 18 ten-second captures takes a minute or two of pressing Enter.
exec ./build/accelcal wizard --source sim --speed 20 "$@"

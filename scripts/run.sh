#!/usr/bin/env bash
# Installs what is missing, builds, and runs the calibration wizard on the virtual bench: full
# screen on a terminal, plain prompts otherwise. Extra arguments go to `accelcal wizard` and
# override the defaults below (e.g. --speed 1 for real time, --source serial:/dev/ttyUSB0@115200,
# --session FILE to resume one, --plain).
# ACCELCAL=PROGRAM runs that program instead of building one (an installed accelcal; the tests).
set -euo pipefail
program=${ACCELCAL:-}
if [ -z "$program" ]; then
  repo=$(cd "$(dirname "$0")/.." && pwd)
  "$repo/scripts/setup.sh" --no-test   # Chromium is for the tests only
  # The program alone: the tests and benchmarks are for scripts/test.sh and scripts/bench.sh.
  (cd "$repo" && BUILD_TARGETS=accelcal ./scripts/build.sh -DACCELCAL_UNITY=ON)  # batches: half the compile time
  program=$repo/build/accelcal
fi

# The defaults, each left out when the arguments give it (CLI11 takes an option once):
# --speed 20 runs the simulated bench 20 times faster than real time, so a whole session of 21
# captures (as long as the procedure's capture plan makes them) takes a minute or two of
# pressing Enter.
declare -A defaults=([--source]=sim [--speed]=20)
for arg in "$@"; do
  name=${arg%%=*}
  [ -n "${defaults[$name]+given}" ] && unset "defaults[$name]"
done
args=()
for name in --source --speed; do
  [ -n "${defaults[$name]+kept}" ] && args+=("$name" "${defaults[$name]}")
done
exec "$program" wizard "${args[@]}" "$@"

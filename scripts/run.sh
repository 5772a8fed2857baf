#!/usr/bin/env bash
# Installs what is missing, builds, and runs accelcal on the virtual bench: a simulated
# calibration session (the default scenario), its fit, and the calibration file.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh
out=${ACCELCAL_DEMO_DIR:-$(mktemp -d)}
mkdir -p "$out"
./build/accelcal simulate scenarios/bench_default.toml -o "$out/captures.csv" --truth "$out/truth.json"
./build/accelcal fit "$out/captures.csv" -o "$out/cal.json"
echo
echo "files in $out: captures.csv (the simulated captures), truth.json (the bench's true"
echo "parameters, to compare), cal.json (the calibration)"

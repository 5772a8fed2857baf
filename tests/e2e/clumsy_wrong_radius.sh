#!/usr/bin/env bash
# The clumsy bench (scenarios/clumsy_wrong_radius.toml): asked for 0.10 m, the technician mounts
# the sensor at 0.15 m. The run is refused with what the measurement fits; the retry is right.
# Usage: bash clumsy_wrong_radius.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure
wizard clumsy_wrong_radius.toml "$work/s.db" ''
said "centripetal 15.8 m/s^2 expected from 120 rpm at 0.1 m, 2"
said " m at 120 rpm)"
said "check the mounting, radius and speed; Enter tries again"
said "Verdict: PASS"
calibration "$work/s.db"
within_truth 4
echo "clumsy_wrong_radius: ok"

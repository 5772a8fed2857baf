#!/usr/bin/env bash
# The clumsy bench (scenarios/clumsy_wrong_axis.toml), issue 12 problem 2: at "+x radial, +z up"
# the technician mounts the sensor with +y outward. Once it was accepted and stored as "+x
# radial"; now it is refused naming the radial axis, and the retry is right.
# Usage: bash clumsy_wrong_axis.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure
wizard clumsy_wrong_axis.toml "$work/s.db" ''
said "problem: wrong mounting: the samples show +y radial, +z up (the centripetal "
said "is on y), not +x radial, +z up: mount the sensor with +x pointing away from the spin axis and +z up"
said "hint: stop the table, mount the sensor +x radial, +z up as asked and start the table again; Enter tries again"
said "Verdict: PASS"
calibration "$work/s.db"
within_truth 4
# The finished session opened again says its verdict and numbers, not a bare "complete".
mv "$work/out" "$work/first_out"
wizard clumsy_wrong_axis.toml "$work/s.db" ''
said "Verdict: PASS"
said "bias (counts)"
said "Calibration complete (in an earlier run): nothing left to do."
echo "clumsy_wrong_axis: ok"

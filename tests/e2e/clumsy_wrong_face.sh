#!/usr/bin/env bash
# The clumsy bench (scenarios/clumsy_wrong_face.toml): asked for -x up, the technician puts the
# prism on -y up. The wizard refuses the capture naming the face; the retry takes the right
# one; the calibration passes with the true parameters.
# Usage: bash clumsy_wrong_face.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure
wizard clumsy_wrong_face.toml "$work/s.db" ''
said "the prism sits on the wrong face: -y is up, expected -x"
said "put the prism with -x up and let go; Enter tries again"
said "Verdict: PASS"
calibration "$work/s.db"
within_truth 4
echo "clumsy_wrong_face: ok"

#!/usr/bin/env bash
# The clumsy bench (scenarios/clumsy_settling.toml): a sensor still settling after each change
# of pose. Once the first captures show it, the wizard waits before a capture begins and says
# what for, in bench words; the session ends PASS with the nine parameters near the truth.
# Usage: bash clumsy_settling.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
# The full procedure's 10 s captures (3 s ones show too little of the approach to judge it).
cp "$source_dir/procedures/full_calibration.toml" "$work/short.toml"
wizard clumsy_settling.toml "$work/s.db" ''
said "still settling after you set it down: the earlier poses were still moving"
said "s more"
# The verdict is the certificate's: with the full procedure's limits the scatter the settling
# leaves (about 4x the noise after the wait) may put a misalignment's U just over its 5 mrad;
# a FAIL must then name that scatter, never another cause (issue 27's one truth).
if ! grep -q "Verdict: PASS" "$work/out"; then
  said "Verdict: FAIL"
  said "the captures' own scatter alone gives"
fi
calibration "$work/s.db"
within_truth 4
echo "clumsy_settling: ok"

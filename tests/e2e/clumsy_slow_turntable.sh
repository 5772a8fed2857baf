#!/usr/bin/env bash
# The clumsy bench (scenarios/clumsy_slow_turntable.toml): the turntable turns 1 % slower than
# stated. With the local gravity known, the diagnosis finds the speed scale and the calibration
# is right, but not PASS (issue 27, item 4): the lab's turntable is verified to 0.02 %, so either
# that verification or the gravity is wrong, and both checks are named. On the standard value
# it names the gravity ambiguity and the report cannot PASS.
# Usage: bash clumsy_slow_turntable.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure
wizard clumsy_slow_turntable.toml "$work/g.db" '\n\n\n9.80665 +- 0.00001\n'
said "rpm_scale"
said "Verdict: INCOMPLETE"
said "the turntable's speed is verified to u = 0.02 % (SIM-TT-01, calibration SIM-CAL-2025-018) but the data finds it 1"
said "or the local gravity used, 9.80665 +- 0.00001 m/s^2"
calibration "$work/g.db"
within_truth 4
jq -e '[.effects[] | select(.name == "rpm_scale") | .parameters.rpm_scale] | length == 1 and (.[0] + 0.01 | fabs) < 0.002'   "$work/cal.json" > /dev/null || fail "the speed scale was not found: $(jq -c .effects "$work/cal.json")"
# The standard value typed (the virtual lab offers its measured gravity by default).
wizard clumsy_slow_turntable.toml "$work/std.db" '\n\n\nstandard\n'
said "Gravity: a wrong table speed found while gravity is the standard value"
said "Verdict: FAIL"
said "INCOMPLETE: gravity not established"
echo "clumsy_slow_turntable: ok"

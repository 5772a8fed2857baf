#!/usr/bin/env bash
# The clumsy bench (scenarios/clumsy_tilted_table.toml): the table stands tilted on its feet.
# The leveling (reversal method) says which feet to raise; the technician turns them by 70 %
# of the advice, and the loop converges until the table is level within tolerance.
# Usage: bash clumsy_tilted_table.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure
wizard clumsy_tilted_table.toml "$work/s.db" ''
said "problem: the table is not level: raise the left side by about"
said "raise the back by about"
said "adjust the feet, then Enter to measure again"
grep -q "(tolerance 1.5 deg): level; press Enter to continue" "$work/out" || fail "the leveling never converged"
rounds=$(grep -c "the table is not level" "$work/out")
[ "$rounds" -ge 1 ] && [ "$rounds" -le 5 ] || fail "$rounds leveling rounds"
said "Verdict: PASS"
calibration "$work/s.db"
within_truth 4
echo "clumsy_tilted_table: ok ($rounds rounds)"

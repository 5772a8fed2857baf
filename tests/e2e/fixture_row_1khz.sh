#!/usr/bin/env bash
# A row of 8 boards at 1 kHz (tests/data/fixture/row_8_1khz.toml: --sensors 8's geometry, a
# clamped plate placed square to 0.1 deg, each board's truth stated), the full procedure with
# fixed 10 s captures (--fixed-duration 10: the plan would make them ~3 s at 1 kHz, and
# fixture_row_8.sh runs by the plan). A capture's mean is ten thousand samples; a board away from the
# plate's reference point takes the plate's placement at each turntable run as its own radius
# error (up to 0.2 mm at 120 mm: 20 to 50 x a run's noise). The fit weighs each run by that
# radius's own uncertainty and the budget lists it ("run's own radius"): every board PASSes,
# within 4 sigma of its own truth. Before, the boards 30-120 mm out FAILed on residual RMS over
# noise (6.7 to 20 x).
# Usage: bash fixture_row_1khz.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
data_dir=$3
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/sensor_checks.bash"
command -v jq > /dev/null || { echo "jq missing: skipped"; exit 77; }
scenario="$data_dir/fixture/row_8_1khz.toml"
db="$work/row.db"
wizard_on_enter --source sim --speed 0 --scenario "$scenario" --fixed-duration 10 --session "$db"
batch="$work/row.batch.csv"
[ -s "$batch" ] || fail "no batch summary beside the session"

for n in 1 2 3 4 5 6 7 8; do
  serial=$(printf 'R%02d' "$n")
  grep -q "^$n,\"$serial\",PASS," "$batch" || { cat "$batch" >&2; fail "$serial does not conform"; }
  board_truth "$scenario" "$serial" > "$work/truth_$n.json"
  sensor_within_truth "$n" "$serial" 4
done

# The far board's budget names the run's own radius, and its certificate prints the same U
# the verdict was decided on: the line is in the report's budget, beside the fit's type A.
"$accelcal" report "$db" --sensor 8 --format json -o "$work/r8.json" > /dev/null
line="run's own radius"
jq -e --arg q "$line" '[.. | objects | select(.quantity? == $q)] | length > 0' "$work/r8.json" \
  > /dev/null || fail "R08's budget has no line for the run's own radius"
"$accelcal" report "$db" --sensor 4 --format json -o "$work/r4.json" > /dev/null
jq -e --arg q "$line" '[.. | objects | select(.quantity? == $q)] | length == 0' "$work/r4.json" \
  > /dev/null || fail "R04, at the reference point, has a radius-of-each-run line"
# Its report says what its residuals are held to: noise and the runs' own radii.
"$accelcal" report "$db" --sensor 8 > "$work/r8.txt"
grep -q "RMS of their noise and own radii:" "$work/r8.txt" || fail "R08's report does not say its sigma holds the radii"
echo "fixture_row_1khz: ok"

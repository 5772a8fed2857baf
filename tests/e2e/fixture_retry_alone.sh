#!/usr/bin/env bash
# A loose board retried alone, end to end (issue 31; app/fixture/fixture_driver.h): the plate of
# tests/data/fixture/plate_8_faults.toml with its loose board (B02) rocking on for 20 s after each
# placement (loose_rock_s), longer than the plate takes to settle. At a pose the others are
# taken and B02 is named, left out for not being still; Enter (the recommended answer: its link
# is up, the plate held) takes it alone while the plate stays, and it is taken alone. At the end
# B02 has its calibration like the others, within 4 sigma of its truth.
# Usage: bash fixture_retry_alone.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
data_dir=$3
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/sensor_checks.bash"
command -v jq > /dev/null || { echo "jq missing: skipped"; exit 77; }
scenario="$work/loose_20s.toml"
sed 's/^loose_deg = 3.0$/loose_deg = 3.0\nloose_rock_s = 20.0/' "$data_dir/fixture/plate_8_faults.toml" > "$scenario"
grep -q '^loose_rock_s = 20.0$' "$scenario" || fail "the scenario's loose board was not found to make it rock longer"
db="$work/plate.db"
wizard_on_enter --source sim --speed 0 --scenario "$scenario" --session "$db"
grep -q "sensor 2 (B02) left out of '[^']*': not still while the others were" "$work/out" ||
  { grep B02 "$work/out" | head >&2; fail "the rocking board was never left out of a pose"; }
grep -q "Enter: retry sensor 2 (B02)" "$work/out" || fail "a retry alone was not what Enter recommended"
grep -q "capturing sensor 2 (B02) alone: keep the plate still" "$work/out" || fail "B02 was never captured alone"
grep -q "sensor 2 (B02) taken alone at '" "$work/out" || fail "B02 was never taken alone"
grep -q '^2,"B02",PASS,' "$work/plate.batch.csv" || { cat "$work/plate.batch.csv" >&2; fail "B02 does not conform"; }
board_truth "$scenario" B02 > "$work/truth_2.json"
sensor_within_truth 2 "B02, taken alone where it rocked" 4
echo "fixture_retry_alone: ok"

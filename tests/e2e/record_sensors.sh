#!/usr/bin/env bash
# `accelcal record --sensors N` (issue 31): a plate of boards recorded at once, one recording per
# board beside -o's name, each a recording `fit --recording` and `allan` read; a dead board named,
# without a file; `-o -` refused (several files). And the wizard's record step on a plate: each
# board's own record.
# Usage: bash record_sensors.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
source "$(dirname "$0")/lib/common.bash"

# Four healthy boards, 30 s at 100 Hz each.
expect 0 "$accelcal" record --source sim --speed 0 --sensors 4 --duration 30 -o "$work/plate.txt"
for n in 01 02 03 04; do
  [ -s "$work/plate.SIM$n.txt" ] || { cat "$work/err"; fail "no recording of SIM$n"; }
  [ "$(grep -vc '^#' "$work/plate.SIM$n.txt")" -eq 3000 ] || fail "SIM$n: not 3000 samples"
  grep -q "SIM$n: 3000 samples written to $work/plate.SIM$n.txt" "$work/err" || { cat "$work/err"; fail "SIM$n not said"; }
done
grep -q "duration reached" "$work/err" || fail "stop reason"
# Each board its own noise: the same moments, not the same readings.
cmp -s <(grep -v '^#' "$work/plate.SIM01.txt" | cut -d' ' -f1) <(grep -v '^#' "$work/plate.SIM02.txt" | cut -d' ' -f1) ||
  cmp -s <(grep -v '^#' "$work/plate.SIM01.txt" | cut -d, -f1) <(grep -v '^#' "$work/plate.SIM02.txt" | cut -d, -f1) ||
  fail "the boards' recordings are not of the same moments"
cmp -s "$work/plate.SIM01.txt" "$work/plate.SIM02.txt" && fail "two boards recorded the same readings"
# A board's recording is a recording: its Allan deviation on its own.
expect 0 "$accelcal" allan "$work/plate.SIM03.txt" -o "$work/allan.json"
[ -s "$work/allan.json" ] || fail "no Allan deviation of SIM03"

# The faulty plate: board 5 is dead from the start; the other seven are recorded.
expect 0 "$accelcal" record --source sim --speed 0 --scenario "$data/fixture/plate_8_faults.toml" \
  --duration 10 -o "$work/faults.txt"
[ "$(ls "$work"/faults.B0*.txt | wc -l)" -eq 7 ] || { ls "$work"; fail "not 7 recordings"; }
[ -e "$work/faults.B05.txt" ] && fail "a file for the dead board"
grep -q "B05: sent no samples while the others did" "$work/err" || { cat "$work/err"; fail "the dead board not named"; }

# The wizard's record step on a plate of 3 (the noise procedure): the lead's record, and each
# other board's samples of the same minute as its own record, read by `allan --step`.
{ yes '' || true; } | "$accelcal" wizard --source sim --speed 0 --sensors 3 --procedure noise.toml \
  --session "$work/noise.db" --plain > "$work/wizard.out" 2>&1 || { tail "$work/wizard.out"; fail "noise wizard"; }
for serial in SIM01 SIM03; do
  expect 0 "$accelcal" allan "$work/noise.db" --step "noise@$serial"
  grep -q "Allan deviation of $work/noise.db:noise@$serial" "$work/out" || { cat "$work/out"; fail "no record of $serial"; }
  grep -qE '^(5999|6000|6001) samples at 100 Hz' <(sed -n 2p "$work/out") || { cat "$work/out"; fail "$serial: not a minute of samples"; }
done
expect 0 "$accelcal" allan "$work/noise.db" --step noise
cmp -s <("$accelcal" allan "$work/noise.db" --step noise@SIM01) "$work/out" && fail "SIM01's record is the lead's"

# Several files cannot go to standard output.
expect 1 "$accelcal" record --source sim --sensors 3 --duration 1 -o -
grep -q "several sensors are written one recording each" "$work/err" || { cat "$work/err"; fail "-o - not refused"; }
echo "record_sensors: ok"

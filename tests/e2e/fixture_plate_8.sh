#!/usr/bin/env bash
# Issue 31's done-when, on the virtual bench: a fixture of 8 boards (tests/data/fixture/
# plate_8_faults.toml: board 2 loose, board 5 dead from the start, board 7 turned a quarter
# turn) calibrated in one wizard session, each pose taken once for all. Killed mid-session and
# resumed: every sensor keeps its captures. At the end: 7 calibrations, each within 4 sigma of
# its own board's truth, the dead board named with why, a report with its own certificate per
# board, and the batch summary (beside the session and from `report --format batch-csv`).
# Usage: bash fixture_plate_8.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
data_dir=$3
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
. "$source_dir/tests/e2e/lib/sensor_checks.bash"
command -v jq > /dev/null || { echo "jq missing: skipped"; exit 77; }
short_procedure
db="$work/plate.db"
# No --fixed-duration: the session runs by the capture plan, as a one-sensor session does (each
# board's turntable radius, only as good as each mounting, is in its fit's weights and budget:
# docs/fixtures.md). Checked at the end: every board's captures the plan's length, beyond the
# steps' own 3 s.
run() {  # the wizard on the plate, answers all Enter
  { yes '' || true; } | "$accelcal" wizard --source sim --speed 0 \
    --scenario "$data_dir/fixture/plate_8_faults.toml" --procedure "$work/short.toml" \
    --session "$db" --plain
}

# A first run given the answers up to the sixth pose only (the fifth, +y up, taken), so that it
# waits there whatever the machine's speed, then killed; resumed to the end. The resume puts
# the source's restarted clock on the session's (app/wizard/session_clock.h): every board's
# samples must follow the lead's onto it, turntable runs included (their accepted samples have
# the table's swing taken out, so they cannot be matched with the source's by their readings).
mkfifo "$work/answers"
"$accelcal" wizard --source sim --speed 0 --scenario "$data_dir/fixture/plate_8_faults.toml" \
  --procedure "$work/short.toml" --session "$db" --plain < "$work/answers" > "$work/out.1" 2>&1 &
pid=$!
exec 3> "$work/answers"
# Enter to each question (the fixture's about a board left out among them: how many depends
# on the loose board) until step 8 shows; then no more answers.
answered_at=-1
for _ in $(seq 6000); do
  grep -q '^\[8/' "$work/out.1" 2>/dev/null && break  # step 8: five poses taken
  kill -0 "$pid" 2>/dev/null || break
  size=$(stat -c %s "$work/out.1")
  # The prompt seen may be step 8's, printed after the check above: looked for again after it.
  if [ "$size" != "$answered_at" ] && [ "$(tail -c 2 "$work/out.1")" = "> " ] &&
     ! grep -q '^\[8/' "$work/out.1"; then
    printf '\n' >&3
    answered_at=$size
  fi
  sleep 0.01
done
kill -0 "$pid" 2>/dev/null || { cat "$work/out.1" >&2; fail "the first run ended before it was killed"; }
kill -9 "$pid"
wait "$pid" 2>/dev/null || true
exec 3>&-
before=$(captures_of 1)
[ "$before" -eq 5 ] || fail "the first run, killed at the sixth pose, holds $before captures of sensor 1, not 5"

run > "$work/out" 2> "$work/err" || { tail -30 "$work/out" >&2; cat "$work/err" >&2; fail "the resumed wizard failed"; }
said "Resuming session"

# Every sensor but the dead one: its captures kept across the kill, its calibration near its truth.
for n in 1 2 3 4 6 7 8; do
  serial=$(printf 'B%02d' "$n")
  board_truth "$data_dir/fixture/plate_8_faults.toml" "$serial" > "$work/truth_$n.json"
  sensor_within_truth "$n" "sensor $n ($serial)" 4
  sensor_report_checked plate "$serial"
done
[ "$(sort -u "$work/numbers" | wc -l)" -eq 7 ] || { cat "$work/numbers" >&2; fail "7 certificates, each its own number"; }

# The dead board: no calibration, named with why; the others have their verdicts.
"$accelcal" report "$db" --format batch-csv -o "$work/batch.csv" > /dev/null
cmp -s "$work/batch.csv" "$work/plate.batch.csv" || fail "the batch summary beside the session differs from report's"
head -1 "$work/batch.csv" | grep -qx 'sensor,serial,verdict,bias_x,bias_y,bias_z,scale_x,scale_y,scale_z,a_yz,a_zy,a_zx,reason' ||
  fail "batch header"
[ "$(tail -n +2 "$work/batch.csv" | wc -l)" -eq 8 ] || fail "8 rows"
grep -q '^5,"B05",NO CALIBRATION,,,,,,,,,,"no capture' "$work/batch.csv" || { cat "$work/batch.csv" >&2; fail "the dead board, named"; }
[ "$(grep -cE '^[0-9],"B0[0-9]",(PASS|FAIL|INCOMPLETE|NO LIMITS STATED),' "$work/batch.csv")" -eq 7 ] ||
  { cat "$work/batch.csv" >&2; fail "7 verdicts"; }
# Every board that is not dead took every pose after the resume too (the nine turntable runs
# all come after it), and each board without a fault passes, as the lead does.
for n in 1 2 3 4 6 7 8; do
  runs=$(captures_of "$n" turntable)
  [ "$runs" -eq 9 ] || { grep 'left out' "$work/out" >&2; fail "sensor $n: $runs turntable runs of 9 after the resume"; }
done
for n in 1 3 4 6 7 8; do
  grep -q "^$n,\"B0$n\",PASS," "$work/batch.csv" || { cat "$work/batch.csv" >&2; fail "board $n (no fault) passes"; }
done
said "B05"
# Line mode: a line per board after each pose; the dead board asked about, Enter leaving it out.
said "sensor 3 (B03): taken, still"
said "sensor 7 (B07): taken, still"
said "sensor 5 (B05): left out of"
said "Keep the plate as it is. Enter: leave out sensor 5 (B05)"
# The dead board is asked about once a run: left out then, it is left out of every later pose
# without a question while its link stays down, each time said.
[ "$(grep -c 'Enter: leave out sensor 5 (B05)' "$work/out")" -eq 1 ] || fail "the dead board asked about more than once"
grep -q "sensor 5 (B05) left out of '[^']*' as before: its link is still down" "$work/out" ||
  fail "the dead board's later poses are not said"
[ "$(grep -c '^  sensor [0-9] (B0[0-9]): ' "$work/out")" -ge $((8 * 9)) ] || fail "not a line per board for every turntable run"
# Each board is a device of its own: its calibration in this session is its history's.
"$accelcal" history B03 --sessions-dir "$work" --format json > "$work/history.json" ||
  fail "no history of B03"
jq -e '.calibrations | length == 1' "$work/history.json" > /dev/null || { cat "$work/history.json" >&2; fail "B03: one calibration"; }
jq -e --slurpfile c "$work/cal_3.json" '.calibrations[0].parameters.bias_x.value == $c[0].bias_counts[0] and
  .calibrations[0].parameters.bias_z.value == $c[0].bias_counts[2] and .device == "B03"' "$work/history.json" > /dev/null ||
  { head -c 600 "$work/history.json" >&2; fail "B03's history is not its own calibration"; }
# The plan's captures, the same moments for every board: each capture of B03 holds as many
# samples as the lead's (B04) of the same pose, within 3 % (a board's own clock), and more than
# the steps' own 3 s (300 samples at 100 Hz) would.
counts() {  # SENSOR -> "capture_id count" per capture
  "$accelcal" export "$db" --sensor "$1" -o "$work/counts_$1.csv" > /dev/null
  grep -v '^#' "$work/counts_$1.csv" | tail -n +2 | cut -d, -f1 | uniq -c | awk '{ print $2, $1 }'
}
counts 3 > "$work/b03.counts"
counts 4 > "$work/b04.counts"
join "$work/b03.counts" "$work/b04.counts" |
  awk '$2 < 0.97 * $3 || $2 > 1.03 * $3 || $2 < 400 { bad = 1 } END { exit bad || NR < 18 }' ||
  { join "$work/b03.counts" "$work/b04.counts" >&2; fail "B03's captures are not the plan's, as the lead's"; }
echo "fixture_plate_8: ok"

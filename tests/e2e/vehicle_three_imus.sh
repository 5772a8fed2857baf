#!/usr/bin/env bash
# Issue 31's done-when over MAVLink: a flight controller with three IMUs (the node-mavlink test
# vehicle, tests/peers/mavlink_vehicle.cjs, sending what ArduPilot sends: RAW_IMU of IMU 0,
# SCALED_IMU2 and SCALED_IMU3), each IMU with its own truth, calibrated in one wizard session on
# one MAVLink link (`--source mavlink:... --fixture vehicle_3imu.toml`: sensor i is IMU instance
# i), the virtual bench behind the vehicle placing the whole board (lib/remote_bench.bash).
#   - killed (kill -9) while it waits at the sixth pose, resumed: every IMU keeps its captures;
#   - at the end: 3 verdicts, each IMU's calibration within 4 sigma of its own truth, a report
#     with its own certificate per IMU, the batch summary beside the session and from `report
#     --format batch-csv`.
# Usage: bash vehicle_three_imus.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
data_dir=$3
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
. "$source_dir/tests/e2e/lib/remote_bench.bash"
. "$source_dir/tests/e2e/lib/sensor_checks.bash"
. "$source_dir/tests/peers/node_peers.bash"
trap 'stop_bench; rm -rf "$work"' EXIT
command -v jq > /dev/null || { echo "jq missing: skipped"; exit 77; }
need_node_peers
# The autopilot procedure (counts of 0.001 m/s^2), 3 s captures, without its write-back (one IMU
# at a time is written back: mavlink:...,imu=N).
python3 - "$source_dir/procedures/autopilot_imu.toml" "$work/short.toml" <<'PY'
import sys
text = open(sys.argv[1]).read().replace("capture_duration_s = 10 ", "capture_duration_s = 3 ")
head, *steps = text.split("\n[[step]]")
open(sys.argv[2], "w").write(head + "".join("\n[[step]]" + s for s in steps if 'kind = "write_back"' not in s))
PY
grep -q '^capture_duration_s = 3 ' "$work/short.toml" || fail "short procedure: no capture_duration_s"
grep -q 'kind = "write_back"' "$work/short.toml" && fail "short procedure: the write-back left"

# The bench's sensor (the quiet scenario's [sensor]), which the vehicle takes back to the
# platform's specific force, and each IMU's truth: bias counts; scale counts/(m/s^2);
# misalignment a_yz, a_zy, a_zx rad.
quiet_scenario "$work/quiet.toml"
bench_scenario=$work/quiet.toml
bench_truth='32820.8,32633.6,33004.8;553.92,561.12,550.56;0.0042,-0.0031,0.0057'
grep -q '^misalignment_rad = { yz = 0.0042, zy = -0.0031, zx = 0.0057 }' "$work/quiet.toml" ||
  fail "the bench's misalignment is not the one the vehicle is told"
truths=('35,-22,48;1002.5,997.1,1005.3;0.0031,-0.0024,0.0047'
        '-61,17,-30;995.4,1003.8,998.2;-0.0052,0.0013,-0.0021'
        '12,84,-57;1007.9,992.6,1001.1;0.0018,0.0061,-0.0035')
start_bench 20 node "$source_dir/tests/peers/mavlink_vehicle.cjs" --tcp 0 --msg ardupilot \
  --bench-truth "$bench_truth" --imu-truth "${truths[0]}" --imu-truth "${truths[1]}" \
  --imu-truth "${truths[2]}" --summary "$work/vehicle.json"
mav="mavlink:tcp:127.0.0.1:$peer_port"
fixture=$data_dir/fixture/vehicle_3imu.toml
db=$work/fc.db
REPORT_ARGS=(--procedure "$work/short.toml")  # the session ran the autopilot procedure

# The welcome's answers: the vehicle's serial, the operator, the place, the bench's gravity and
# its identified equipment (the virtual bench's lab, scenarios/bench_default.toml [lab]).
welcome='FC1\ntester\n\n9.80665 +- 0.00002\nruler id SIM-RUL-01 u 0.03 cal SIM-CAL-2025-017; turntable id SIM-TT-01 u 0.02 cal SIM-CAL-2025-018; level id SIM-LVL-01; prism id SIM-PR-01\n'

# A first run given the answers up to the sixth pose only (the fifth, +y up, taken), so that it
# waits there whatever the machine's speed; killed there (kill -9), then resumed to the end.
mkfifo "$work/answers"
"$accelcal" wizard --source "$mav" --fixture "$fixture" --bench-control "127.0.0.1:$bench_port" \
  --procedure "$work/short.toml" --session "$db" --plain < "$work/answers" > "$work/out.1" 2>&1 &
pid=$!
exec 3> "$work/answers"
printf "$welcome" >&3
printf '\n%.0s' $(seq 9) >&3
kill_at_step "$pid" "$work/out.1" 8  # step 8: five poses taken
exec 3>&-
grep -q '^\[8/.*-y up' "$work/out.1" || fail "the first run was not at the sixth pose (-y up)"
for n in 1 2 3; do
  before=$(captures_of "$n")
  [ "$before" -eq 5 ] || fail "the first run, killed at the sixth pose, holds $before captures of IMU $((n - 1)), not 5"
done

set +e
yes '' | timeout 600 "$accelcal" wizard --source "$mav" --fixture "$fixture" \
  --bench-control "127.0.0.1:$bench_port" --procedure "$work/short.toml" --session "$db" --plain \
  > "$work/out" 2> "$work/err"
code=${PIPESTATUS[1]}
set -e
[ "$code" -eq 0 ] || { tail -40 "$work/out" >&2; cat "$work/err" >&2; fail "the resumed wizard exited $code"; }
said "Resuming session"
# The IMUs read as ArduPilot sends them: RAW_IMU for IMU 0, SCALED_IMU2 and SCALED_IMU3.
said "no HIGHRES_IMU of IMU 0 came; reading RAW_IMU instead"

# Each IMU: every pose taken (the five before the kill kept), its calibration within 4 sigma of
# its own truth, its own report and certificate number.
for n in 1 2 3; do
  serial="FC1-ACC$((n - 1))"
  [ "$(captures_of "$n" static)" -eq 9 ] || fail "IMU $((n - 1)): not 9 static poses after the resume"
  [ "$(captures_of "$n" turntable)" -eq 9 ] || fail "IMU $((n - 1)): not 9 turntable runs after the resume"
  IFS=';' read -r b k m <<< "${truths[$((n - 1))]}"
  IFS=',' read -r yz zy zx <<< "$m"
  echo "{\"bias_counts\": [$b], \"scale_counts_per_mps2\": [$k], \"misalignment_rad\": {\"yz\": $yz, \"zy\": $zy, \"zx\": $zx}}" > "$work/truth_$n.json"
  sensor_within_truth "$n" "IMU $((n - 1))" 4
  sensor_report_checked fc "$serial"
done
[ "$(sort -u "$work/numbers" | wc -l)" -eq 3 ] || { cat "$work/numbers" >&2; fail "3 certificates, each its own number"; }

# The batch summary: beside the session and from report, one row per IMU, each with its verdict.
# (report takes the limits from the procedure given: the session ran the autopilot one.)
"$accelcal" report "$db" --procedure "$work/short.toml" --format batch-csv -o "$work/batch.csv" > /dev/null
cmp -s "$work/batch.csv" "$work/fc.batch.csv" || {
  diff "$work/batch.csv" "$work/fc.batch.csv" >&2; fail "the batch summary beside the session differs from report's"; }
head -1 "$work/batch.csv" | grep -qx 'sensor,serial,verdict,bias_x,bias_y,bias_z,scale_x,scale_y,scale_z,a_yz,a_zy,a_zx,reason' ||
  fail "batch header"
[ "$(tail -n +2 "$work/batch.csv" | wc -l)" -eq 3 ] || fail "3 rows"
for n in 1 2 3; do
  grep -q "^$n,\"FC1-ACC$((n - 1))\",PASS," "$work/batch.csv" || { cat "$work/batch.csv" >&2; fail "IMU $((n - 1)) passes"; }
done
stop_bench

# The same vehicle with IMU 2 silent from the start: the session goes on with the other two, and
# the silent one is named with why, never calibrated.
start_bench 20 node "$source_dir/tests/peers/mavlink_vehicle.cjs" --tcp 0 --msg ardupilot \
  --bench-truth "$bench_truth" --imu-truth "${truths[0]}" --imu-truth "${truths[1]}" \
  --imu-truth "${truths[2]}" --silent-imu 2
mav="mavlink:tcp:127.0.0.1:$peer_port"
db=$work/silent.db
set +e
{ printf "$welcome"; yes ''; } | timeout 600 "$accelcal" wizard --source "$mav" --fixture "$fixture" \
  --bench-control "127.0.0.1:$bench_port" --procedure "$work/short.toml" --session "$db" --plain \
  > "$work/out" 2> "$work/err"
code=${PIPESTATUS[1]}
set -e
stop_bench
[ "$code" -eq 0 ] || { tail -40 "$work/out" >&2; cat "$work/err" >&2; fail "the wizard (IMU 2 silent) exited $code"; }
"$accelcal" report "$db" --procedure "$work/short.toml" --format batch-csv -o "$work/batch.csv" > /dev/null
grep -q '^3,"FC1-ACC2",NO CALIBRATION,,,,,,,,,,"no capture' "$work/batch.csv" ||
  { cat "$work/batch.csv" >&2; fail "the silent IMU 2, named"; }
for n in 1 2; do
  grep -q "^$n,\"FC1-ACC$((n - 1))\",PASS," "$work/batch.csv" || { cat "$work/batch.csv" >&2; fail "IMU $((n - 1)) passes beside a silent one"; }
done
echo "vehicle_three_imus: ok"

#!/usr/bin/env bash
# Issue 31's done-when over MAVLink: a flight controller with three IMUs (the node-mavlink test
# vehicle, tests/peers/mavlink_vehicle.cjs, sending what ArduPilot sends: RAW_IMU of IMU 0,
# SCALED_IMU2 and SCALED_IMU3), each IMU with its own truth, calibrated in one wizard session on
# one MAVLink link (`--source mavlink:... --fixture vehicle_3imu.toml`: sensor i is IMU instance
# i), the virtual bench behind the vehicle placing the whole board (lib/remote_bench.bash).
#   - killed (kill -9) while it waits at the sixth pose, resumed: every IMU keeps its captures;
#   - each IMU with its own stored calibration on the vehicle (INS_ACCOFFS, INS_ACC2OFFS ...),
#     which the vehicle applies to SCALED_IMU2/3: each read and said at the welcome, and taken
#     back out of that IMU's samples;
#   - at the end: 3 verdicts, each IMU's calibration within 4 sigma of its own truth, a report
#     with its own certificate per IMU, the batch summary beside the session and from `report
#     --format batch-csv`; the command that writes each IMU back named, and run for IMUs 1 and 2
#     (the vehicle's parameters then its sensors' own);
#   - IMU 2's temperature calibration on: the undo refused before any session, naming IMU 2; left
#     in (as-is) with IMU 2 silent: IMU 1's calibration is its truth after the vehicle's
#     correction, far from its own (the undo is what makes the first run right).
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
# The autopilot procedure (counts of 0.001 m/s^2), 3 s captures, with its write-back step (which,
# for several IMUs, leaves the writing to the session's end: one command per IMU).
sed 's/^capture_duration_s = 10 /capture_duration_s = 3 /' "$source_dir/procedures/autopilot_imu.toml" > "$work/short.toml"
grep -q '^capture_duration_s = 3 ' "$work/short.toml" || fail "short procedure: no capture_duration_s"
grep -q 'kind = "write_back"' "$work/short.toml" || fail "short procedure: no write-back step"

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
# Each IMU's own stored calibration on the vehicle (ArduPilot's INS_ACCOFFS m/s^2, INS_ACCSCAL;
# INS_ACC2*, INS_ACC3*), which it applies to what it sends in SCALED_IMU2/3 (RAW_IMU, IMU 0's, is
# before it): the wizard takes each back out, so each IMU is held to its sensor's own truth.
offsets=('0.05,-0.03,0.11' '0.12,-0.08,0.2' '-0.15,0.09,-0.06')
scales=('1.004,0.997,1.002' '1.003,0.996,1.005' '0.995,1.006,1.001')
stored=()
for i in 0 1 2; do
  prefix=INS_ACC$([ "$i" -eq 0 ] || echo $((i + 1)))
  IFS=',' read -r ox oy oz <<< "${offsets[$i]}"
  IFS=',' read -r sx sy sz <<< "${scales[$i]}"
  stored+=(--param "${prefix}OFFS_X=$ox" --param "${prefix}OFFS_Y=$oy" --param "${prefix}OFFS_Z=$oz"
           --param "${prefix}SCAL_X=$sx" --param "${prefix}SCAL_Y=$sy" --param "${prefix}SCAL_Z=$sz")
done
start_bench 20 node "$source_dir/tests/peers/mavlink_vehicle.cjs" --tcp 0 --msg ardupilot \
  --bench-truth "$bench_truth" --imu-truth "${truths[0]}" --imu-truth "${truths[1]}" \
  --imu-truth "${truths[2]}" "${stored[@]}" --summary "$work/vehicle.json"
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
# At the welcome, each IMU's own calibration as read from the vehicle, and taken out.
for i in 0 1 2; do
  prefix=INS_ACC$([ "$i" -eq 0 ] || echo $((i + 1)))
  IFS=',' read -r ox oy oz <<< "${offsets[$i]}"
  flat "$work/out.1" "IMU $i: its own accelerometer calibration ${prefix}OFFS: x $ox, y $oy, z $oz m/s^2" ||
    { cat "$work/out.1" >&2; fail "IMU $i's stored calibration not said at the welcome"; }
done
[ "$(grep -c 'taken out of every sample' "$work/out.1")" -eq 3 ] || fail "not every IMU's calibration taken out"
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
# The write-back step says where the writing is; the closing lines name each IMU's command: IMU
# 0's (RAW_IMU, counts) with the procedure's driver scaling. IMUs 1 and 2 written by them into
# the vehicle, each echoed and read back (node-mavlink's PARAM_SET echo; the values checked below).
said "each is written into the vehicle on its own once all are calibrated"
for i in 0 1 2; do
  grep -q "^  IMU $i (FC1-ACC$i, PASS): accelcal export-cal $db --sensor $((i + 1)) --to $mav,imu=$i .*--apply\$" "$work/out" ||
    { tail -20 "$work/out" >&2; fail "IMU $i's write-back command not named"; }
done
grep -q "^  IMU 0 (FC1-ACC0, PASS): .* --procedure $work/short.toml --apply\$" "$work/out" ||
  fail "IMU 0 (RAW_IMU counts): the command lacks the procedure's scaling"
for i in 1 2; do
  command=$(sed -n "s/^  IMU $i (FC1-ACC$i, PASS): accelcal //p" "$work/out")
  read -r -a words <<< "$command"
  "$accelcal" "${words[@]}" > "$work/write_$i.out" 2>&1 || { cat "$work/write_$i.out" >&2; fail "IMU $i's write-back"; }
  grep -q "^read back: all 6 as written" "$work/write_$i.out" || { cat "$work/write_$i.out" >&2; fail "IMU $i not read back"; }
  grep -q "^PARAM_SET INS_ACC$((i + 1))OFFS_X = " "$work/write_$i.out" || { cat "$work/write_$i.out" >&2; fail "IMU $i: not its own parameters"; }
done
# `record --sensors 3` on the same link takes each IMU's calibration out as the wizard does.
"$accelcal" record --source "$mav" --sensors 3 --duration 1 -o "$work/imus.txt" > /dev/null 2> "$work/record.err" ||
  { cat "$work/record.err" >&2; fail "record --sensors 3 on the vehicle"; }
for i in 0 1 2; do
  grep -q "IMU $i: its own accelerometer calibration" "$work/record.err" || { cat "$work/record.err" >&2; fail "record: IMU $i's calibration not said"; }
done
[ "$(grep -c 'taken out of every sample' "$work/record.err")" -eq 3 ] || fail "record: not every IMU's calibration taken out"
stop_bench
# What the vehicle holds now (its summary): IMU 1's and 2's offsets and scales, their sensors' own
# (ArduPilot's model: offset = bias / 1000 counts per m/s^2, scale = 1000 / K), IMU 0's untouched.
python3 - "$work/vehicle.json" "${truths[1]}" "${truths[2]}" "${offsets[0]}" <<'PY' || fail "the vehicle's parameters after the write-back"
import json, sys
held = json.load(open(sys.argv[1]))["params"]
for imu, truth in ((1, sys.argv[2]), (2, sys.argv[3])):
    b, k, _ = ([float(x) for x in part.split(",")] for part in truth.split(";"))
    for j, axis in enumerate("XYZ"):
        off, scl = held[f"INS_ACC{imu + 1}OFFS_{axis}"], held[f"INS_ACC{imu + 1}SCAL_{axis}"]
        assert abs(off - b[j] / 1000) < 0.01, (imu, axis, off, b[j] / 1000)
        assert abs(scl - 1000 / k[j]) < 0.003, (imu, axis, scl, 1000 / k[j])
for j, axis in enumerate("XYZ"):
    assert abs(held[f"INS_ACCOFFS_{axis}"] - float(sys.argv[4].split(",")[j])) < 1e-6, "IMU 0 written"
PY

# The same vehicle with IMU 2 silent from the start and its temperature calibration on
# (INS_TCAL3_ENABLE 1, which accelcal cannot undo).
start_bench 20 node "$source_dir/tests/peers/mavlink_vehicle.cjs" --tcp 0 --msg ardupilot \
  --bench-truth "$bench_truth" --imu-truth "${truths[0]}" --imu-truth "${truths[1]}" \
  --imu-truth "${truths[2]}" "${stored[@]}" --param INS_TCAL3_ENABLE=1 --silent-imu 2
mav="mavlink:tcp:127.0.0.1:$peer_port"
db=$work/silent.db
# Undo asked: IMU 2 would be calibrated relative to what it holds, so no session starts, and
# the refusal names the IMU, why and what to do.
set +e
printf "$welcome" | timeout 60 "$accelcal" wizard --source "$mav" --fixture "$fixture" \
  --procedure "$work/short.toml" --session "$db" --plain > "$work/out" 2> "$work/err"
code=$?
set -e
[ "$code" -ne 0 ] || fail "a session started with IMU 2's temperature calibration not undoable"
grep -q "tcp:127.0.0.1:$peer_port, IMU 2: the vehicle's own calibration cannot be taken out of its readings: INS_TCAL3_ENABLE is on" "$work/err" ||
  { cat "$work/err" >&2; fail "the refusal does not name IMU 2 and why"; }
grep -q -- "--source mavlink:tcp:127.0.0.1:$peer_port,imu=2 --reset --apply" "$work/err" ||
  { cat "$work/err" >&2; fail "the refusal does not say how to reset IMU 2"; }
[ ! -e "$db" ] || fail "the refused session left a file"
# Left in (--vehicle-calibration as-is): the session goes on with the two IMUs that send, the
# silent one named with why, never calibrated; IMU 1's calibration then describes the sensor
# after the vehicle's correction: raw' = SCAL .* (raw - 1000 OFFS), its own truth off by that.
set +e
{ printf "$welcome"; yes ''; } | timeout 600 "$accelcal" wizard --source "$mav" --fixture "$fixture" \
  --bench-control "127.0.0.1:$bench_port" --procedure "$work/short.toml" --session "$db" --plain \
  --vehicle-calibration as-is > "$work/out" 2> "$work/err"
code=${PIPESTATUS[1]}
set -e
stop_bench
[ "$code" -eq 0 ] || { tail -40 "$work/out" >&2; cat "$work/err" >&2; fail "the wizard (IMU 2 silent) exited $code"; }
[ "$(grep -c 'left in the readings (as asked)' "$work/out")" -eq 3 ] || fail "as-is not said for every IMU"
grep -q "^  IMU 1 (FC1-ACC1): nothing to write: the vehicle's own calibration was left in its readings" "$work/out" ||
  { tail -20 "$work/out" >&2; fail "as-is: IMU 1's write-back not refused"; }
grep -q "^  IMU 2 (FC1-ACC2): nothing to write: no capture" "$work/out" || { tail -20 "$work/out" >&2; fail "the silent IMU 2: nothing to write"; }
said "INS_TCAL3_ENABLE 1 (a temperature calibration corrects the readings)"
"$accelcal" report "$db" --procedure "$work/short.toml" --format batch-csv -o "$work/batch.csv" > /dev/null
grep -q '^3,"FC1-ACC2",NO CALIBRATION,,,,,,,,,,"no capture' "$work/batch.csv" ||
  { cat "$work/batch.csv" >&2; fail "the silent IMU 2, named"; }
for n in 1 2; do
  grep -q "^$n,\"FC1-ACC$((n - 1))\",PASS," "$work/batch.csv" || { cat "$work/batch.csv" >&2; fail "IMU $((n - 1)) passes beside a silent one"; }
done
# IMU 0 (RAW_IMU, before the vehicle's correction) still its own truth; IMU 1 the corrected one's,
# which lies far (beyond 10 sigma in its bias) from its own.
sensor_within_truth 1 "IMU 0 as-is (RAW_IMU)" 4
IFS=';' read -r b k m <<< "${truths[1]}"
python3 - "$b" "$k" "$m" "${offsets[1]}" "${scales[1]}" > "$work/truth_2.json" <<'PY'
import json, sys
b, k, m, off, scl = ([float(x) for x in a.split(',')] for a in sys.argv[1:])
print(json.dumps({"bias_counts": [s * (bi - 1000 * o) for bi, o, s in zip(b, off, scl)],
                  "scale_counts_per_mps2": [s * ki for ki, s in zip(k, scl)],
                  "misalignment_rad": dict(zip(("yz", "zy", "zx"), m))}))
PY
sensor_within_truth 2 "IMU 1 as-is (its truth after the vehicle's correction)" 4
jq -e --argjson b "[${b}]" '[range(3) as $i | ((.bias_counts[$i] - $b[$i]) / .uncertainty.bias_counts[$i]) | fabs] | max > 10' \
  "$work/cal_2.json" > /dev/null || fail "IMU 1 as-is lies near its own truth: the stored calibration made no difference"
echo "vehicle_three_imus: ok"

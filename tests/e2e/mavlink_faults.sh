#!/usr/bin/env bash
# Issue 30, "bad input and faults", MAVLink: each fault played by the node-mavlink test vehicle
# (tests/peers/mavlink_vehicle.cjs) on the virtual bench's stream, and each named with the link
# and what was seen; nothing stored wrong (the samples that do arrive are the bench's, in order).
# Also the links (udp: and udpout:), MAVLink 1, signing, the IMU instance, old firmware's
# REQUEST_DATA_STREAM and SCALED_IMU's 1 mG resolution, a vehicle that reboots, one that drops
# 5 % of its frames, one that falls silent, and the parameter faults of the write-back.
# Usage: bash mavlink_faults.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
. "$source_dir/tests/e2e/lib/remote_bench.bash"
. "$source_dir/tests/peers/node_peers.bash"
trap 'stop_bench; rm -rf "$work"' EXIT
need_node_peers
vehicle=$source_dir/tests/peers/mavlink_vehicle.cjs

# vehicle_record DURATION_S VEHICLE_ARGS... -- SOURCE_OPTIONS: the bench at speed 10 behind a
# vehicle with those faults, `accelcal record` from it over TCP; stderr in $work/err, samples in
# $work/rec.txt (t strictly increasing checked).
vehicle_record() {
  local duration=$1; shift
  local args=() options=""
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do args+=("$1"); shift; done
  [ $# -gt 0 ] && { shift; options=${1:-}; }
  start_bench 10 node "$vehicle" --tcp 0 "${args[@]}"
  set +e
  timeout 120 "$accelcal" record --source "mavlink:tcp:127.0.0.1:$peer_port$options" --duration "$duration" \
    -o "$work/rec.txt" > /dev/null 2> "$work/err"
  local code=$?
  set -e
  stop_bench
  [ "$code" -eq 0 ] || { cat "$work/err" >&2; fail "record (${args[*]}) exited $code"; }
  awk '!/^#/ { if (n++ && $1 <= last) exit 1; last = $1 } END { exit n < 10 }' "$work/rec.txt" \
    || fail "(${args[*]}): fewer than 10 samples, or t not increasing"
}
err_says() { flat "$work/err" "$1" || { cat "$work/err" >&2; fail "not said: $1"; }; }

# Bad CRC, wrong length, a garbage burst, an unknown message: counted, named with the link.
vehicle_record 6 --bad-crc-every 40
err_says "tcp:127.0.0.1:$peer_port: bad CRC on a HIGHRES_IMU frame from system 1 component 1"
vehicle_record 6 --wrong-length-every 40
err_says "a HIGHRES_IMU frame from system 1 component 1"
err_says "with 70 payload bytes (at most 63 expected)"
vehicle_record 6 --garbage-every 60
err_says "tcp:127.0.0.1:$peer_port: 100 bytes that are not MAVLink frames skipped"
vehicle_record 6 --unknown-every 30
err_says "of other messages skipped (latest: message 703710)"

# 5 % of the frames never sent: sequence gaps counted as lost samples (a single one is no gap
# in t: it is within 3 sample intervals).
vehicle_record 10 --drop 0.05
lost=$(sed -n 's/.* \([0-9]*\) samples lost$/\1/p' "$work/err" | tail -1)
[ -n "$lost" ] && [ "$lost" -ge 20 ] && [ "$lost" -le 90 ] || { cat "$work/err"; fail "5 % of ~1000 frames lost: $lost counted"; }

# Signing on, MAVLink 1: read as well.
vehicle_record 4 --sign
err_says "signed (signatures not checked)"
vehicle_record 4 --v1
err_says " MAVLink 1; the vehicle"

# The IMU instance: a second IMU reads twice the first; imu=1 takes it, imu=0 never does.
vehicle_record 4 --second-imu
first=$(awk '!/^#/ {print $4; exit}' "$work/rec.txt")
vehicle_record 4 --second-imu -- ",imu=1"
second=$(awk '!/^#/ {print $4; exit}' "$work/rec.txt")
# The vehicle's driver reads (2 raw - 2048) / 34.8 there: z1 = 2 z0 + 2048 / 34.8 * 1000 counts.
python3 -c "import sys; a, b = float('$first'), float('$second'); sys.exit(0 if abs(b - (2 * a + 58851)) < 1000 else 1)" \
  || fail "imu=1 is not the second IMU: z $first (imu 0) vs $second (imu 1)"

# Old firmware: SET_MESSAGE_INTERVAL unsupported, REQUEST_DATA_STREAM; SCALED_IMU in mG.
vehicle_record 4 --old-firmware --msg scaled
err_says "SET_MESSAGE_INTERVAL unsupported (asked HIGHRES_IMU at 100 Hz): asked the raw-sensor stream at 100 Hz with REQUEST_DATA_STREAM"
err_says "reading SCALED_IMU instead"
err_says "SCALED_IMU of IMU 0 from system 1 component 1 (ArduPilot): m/s^2, taken as counts of 0.001 m/s^2 (resolution: 1 mG = 9.80665 counts)"
grep -q "100.0 Hz" "$work/err" || { cat "$work/err"; fail "the rate asked not reached"; }
# RAW_IMU: the sensor's counts, no undo.
vehicle_record 4 --msg raw --old-firmware
err_says "RAW_IMU of IMU 0 from system 1 component 1 (ArduPilot): counts (resolution: 1 count)"

# A reboot mid-stream: the link drops, comes back, the clock starts again; t goes on.
vehicle_record 12 --reboot-at 1.5
err_says "rebooted (its clock went back"
err_says "link back up"

# A vehicle that falls silent (the link held open): named as gone.
start_bench 10 node "$vehicle" --tcp 0 --silent-after 2
set +e
timeout 60 "$accelcal" record --source "mavlink:tcp:127.0.0.1:$peer_port" --duration 30 -o "$work/rec.txt" \
  > /dev/null 2> "$work/err" &
rec=$!
for _ in $(seq 100); do grep -q "the vehicle is gone" "$work/err" 2>/dev/null && break; sleep 0.1; done
kill -INT "$rec"; wait "$rec"
set -e
stop_bench
# The link dies for want of samples; the heartbeats' stop is its reason, said with it or, when
# they stopped after the samples did (the heartbeat comes once a second), when it comes.
err_says "link dead: no sample for"
err_says "no heartbeat from system 1 component 1 (ArduPilot) for"
err_says "the vehicle is gone (powered off, rebooting, or the link lost)"
grep -Eq "dead, .*\(no sample for [0-9.]+ s: no heartbeat from system 1 component 1" "$work/err" \
  || { cat "$work/err"; fail "the dead link's reason is not the vehicle gone"; }

# udp: (we listen, the vehicle sends to us) and udpout: (we send first, the vehicle answers).
port=$(python3 -c 'import socket; s=socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
start_bench 10 node "$vehicle" --udp-to "$port"
timeout 60 "$accelcal" record --source "mavlink:udp:127.0.0.1:$port" --duration 4 -o "$work/rec.txt" 2> "$work/err" \
  || { cat "$work/err"; fail "udp: record"; }
stop_bench
err_says "HIGHRES_IMU of IMU 0 from system 1 component 1 (ArduPilot)"
start_bench 10 node "$vehicle" --udp-listen 0
timeout 60 "$accelcal" record --source "mavlink:udpout:127.0.0.1:$peer_port" --duration 4 -o "$work/rec.txt" 2> "$work/err" \
  || { cat "$work/err"; fail "udpout: record"; }
stop_bench
err_says "SET_MESSAGE_INTERVAL: accepted"

# Parameters: a vehicle that answers none; a PARAM_SET not echoed; one echoed with another value.
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" -o "$work/c.csv" > /dev/null
"$accelcal" fit "$work/c.csv" -o "$work/cal.json" > /dev/null
start_bench 10 node "$vehicle" --tcp 0 --no-params
expect 1 "$accelcal" wizard --source "mavlink:tcp:127.0.0.1:$peer_port" --session "$work/none.db" --plain
grep -q "the vehicle answered none of the" "$work/out" || { cat "$work/out" "$work/err"; fail "no PARAM answer not said"; }
grep -q "tcp:127.0.0.1:$peer_port: the vehicle's own calibration cannot be taken out of its readings: the vehicle did not answer for INS_ACCOFFS_X" "$work/err" \
  || { cat "$work/err"; fail "no PARAM answer: refusal"; }
[ ! -e "$work/none.db" ] || fail "a session was created for a vehicle that does not answer"
expect 1 "$accelcal" export-cal "$work/cal.json" --to "mavlink:tcp:127.0.0.1:$peer_port" \
  --procedure "$source_dir/procedures/full_calibration.toml" --apply
grep -q "answered no PARAM_REQUEST_READ for .*: nothing was written" "$work/out" || { cat "$work/out"; fail "no answer: write-back"; }
grep -q "^written: none" "$work/out" || fail "no answer: what was written"
stop_bench

start_bench 10 node "$vehicle" --tcp 0 --no-echo INS_ACCSCAL_X
expect 1 "$accelcal" export-cal "$work/cal.json" --to "mavlink:tcp:127.0.0.1:$peer_port" \
  --procedure "$source_dir/procedures/full_calibration.toml" --apply
grep -q "^written: INS_ACCOFFS_X, INS_ACCOFFS_Y, INS_ACCOFFS_Z$" "$work/out" || { cat "$work/out"; fail "no echo: written"; }
grep -q "^stopped: tcp:127.0.0.1:$peer_port: no PARAM_VALUE echoed the PARAM_SET of INS_ACCSCAL_X" "$work/out" || { cat "$work/out"; fail "no echo: stop"; }
grep -q "^not written: INS_ACCSCAL_Y, INS_ACCSCAL_Z$" "$work/out" || fail "no echo: not written"
grep -q "accelcal: error: the write-back to tcp:127.0.0.1:$peer_port stopped" "$work/err" || fail "no echo: error"
stop_bench

start_bench 10 node "$vehicle" --tcp 0 --wrong-echo INS_ACCOFFS_Y
expect 1 "$accelcal" export-cal "$work/cal.json" --to "mavlink:tcp:127.0.0.1:$peer_port" \
  --procedure "$source_dir/procedures/full_calibration.toml" --apply
grep -q "^stopped: tcp:127.0.0.1:$peer_port: INS_ACCOFFS_Y was set to .* but the vehicle echoed .*: it holds that, not the calibration" "$work/out" \
  || { cat "$work/out"; fail "wrong echo"; }
grep -q "^written: INS_ACCOFFS_X$" "$work/out" || fail "wrong echo: written"
stop_bench

# device-info: the vehicle's calibration, a rotation it cannot undo, and the reset.
start_bench 10 node "$vehicle" --tcp 0 --autopilot px4 --param CAL_ACC0_XOFF=0.5 --param SENS_BOARD_ROT=2
expect 0 "$accelcal" device-info --source "mavlink:tcp:127.0.0.1:$peer_port" --listen 2 --reset --apply
for text in "vehicle: system 1 component 1 (PX4)" "stream: HIGHRES_IMU of IMU 0" "CAL_ACC0_?OFF: x 0.5, y 0, z 0 m/s^2" \
            "CAL_ACC0_ID 1310988" "SENS_BOARD_ROT 2 (YAW_90)" "PARAM_SET CAL_ACC0_XOFF = 0 (REAL32)" "read back: all 6 as written"; do
  flat "$work/out" "$text" || { cat "$work/out"; fail "device-info: $text"; }
done
stop_bench
start_bench 10 node "$vehicle" --tcp 0 --param INS_TCAL1_ENABLE=1
expect 1 "$accelcal" record --source "mavlink:tcp:127.0.0.1:$peer_port" --duration 2 -o "$work/rec.txt"
grep -q "INS_TCAL1_ENABLE is on: the vehicle corrects its readings for temperature" "$work/err" || { cat "$work/err"; fail "temperature calibration"; }
expect 0 "$accelcal" record --source "mavlink:tcp:127.0.0.1:$peer_port" --duration 2 -o "$work/rec.txt" --vehicle-calibration as-is
grep -q "left in the readings (as asked)" "$work/err" || fail "as-is not said"
stop_bench
echo "mavlink_faults: ok"

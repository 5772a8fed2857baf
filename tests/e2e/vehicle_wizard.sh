#!/usr/bin/env bash
# Issue 30, the wizard's side of a MAVLink vehicle, end to end in line mode: one session from the
# welcome to the write-back on the node-mavlink test vehicle (tests/peers/mavlink_vehicle.cjs)
# behind the virtual bench (lib/remote_bench.bash), answered one question at a time by
# lib/answer_prompts.py as a technician would (a typed "yes" at the write-back only). The vehicle
# (a quiet sensor) streams SCALED_IMU (1 mG steps) after its own calibration, refuses the HIGHRES_IMU rate
# request and drops 5 % of its frames:
#   - the welcome shows the vehicle's own calibration, and the session records it;
#   - the noise floor says the 1 mG steps limit it (and the session records that);
#   - the source's notices (the coarser stream, samples lost) are said
#     in plain words, each with its figures on a detail line;
#   - after the report the write-back shows its PARAM_SETs and asks; on yes it writes, every
#     value echoed and read back; the vehicle then holds exactly the values shown (its own
#     summary), the same as export-cal's dry run of the session computes; the step is recorded.
# Then a vehicle that does not echo one PARAM_SET: the write-back stops, says which parameters
# were written and which not, and is recorded as stopped. (A session answered by `yes ''`
# declines the write-back: device_sessions.sh.)
# Usage: bash vehicle_wizard.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
. "$source_dir/tests/e2e/lib/remote_bench.bash"
. "$source_dir/tests/peers/node_peers.bash"
trap 'stop_bench; rm -rf "$work"' EXIT
need_node_peers
sed -e 's/^capture_duration_s = 10 /capture_duration_s = 3 /' \
  "$source_dir/procedures/autopilot_imu.toml" > "$work/autopilot.toml"
grep -q '^kind = "write_back"' "$work/autopilot.toml" || fail "the autopilot procedure has no write_back step"

# A quiet sensor (about 0.9 mG of noise): the vehicle's 1 mG steps are as coarse as its noise, so
# the noise floor is the rounding's as much as the sensor's.
quiet_scenario "$work/quiet.toml"
bench_scenario=$work/quiet.toml
start_bench 20 node "$source_dir/tests/peers/mavlink_vehicle.cjs" --tcp 0 --msg scaled --drop 0.05 \
  --scale 556.8 --bias 32768 \
  --summary "$work/vehicle.json" --param INS_ACCOFFS_X=0.3 --param INS_ACCSCAL_Y=1.03
mav="mavlink:tcp:127.0.0.1:$peer_port"
set +e
python3 "$source_dir/tests/e2e/lib/answer_prompts.py" --first BENCH-9 --first tester \
  --when "Write this calibration into the vehicle?=yes" -- \
  "$accelcal" wizard --source "$mav" --bench-control "127.0.0.1:$bench_port" \
  --procedure "$work/autopilot.toml" --session "$work/v.db" --plain > "$work/out" 2> "$work/err"
code=$?
set -e
[ "$code" -eq 0 ] || { tail -40 "$work/out" >&2; cat "$work/err" >&2; fail "wizard on $mav exited $code"; }

# The welcome: the vehicle's own calibration, shown and recorded.
said "The device's own calibration, as it holds it now:"
said "INS_ACCOFFS: x 0.3"
said "taken out of every sample"
session_input() {  # STEP KEY: the value the session recorded
  python3 - "$work/v.db" "$1" "$2" <<'PY'
import sqlite3, sys
db = sqlite3.connect(sys.argv[1])
rows = db.execute("SELECT value FROM inputs WHERE step_id = ? AND key = ?", (sys.argv[2], sys.argv[3])).fetchall()
print(rows[-1][0] if rows else "")
PY
}
session_input welcome device_calibration > "$work/recorded"
flat "$work/recorded" "INS_ACCOFFS: x 0.3" || { cat "$work/recorded"; fail "the vehicle's calibration not recorded"; }

# The noise floor: the 1 mG steps said where they limit it, and recorded.
said "Limited by the resolution: the readings come in steps of 9.81 counts (1 mG)"
session_input noise_floor resolution > "$work/recorded"
flat "$work/recorded" "steps of 9.81 counts" || fail "the resolution not recorded at the noise floor"

# The source's notices in plain words, the figures under each.
said "source: The device does not send its finest readings"
said "detail: tcp:127.0.0.1:$peer_port: no HIGHRES_IMU of IMU 0 came; reading SCALED_IMU instead"
said "source: Samples are being lost between the device and this computer"
grep -q "^source: " "$work/out" && fail "a notice without its indentation"

# The write-back: shown, asked, written on yes, echoed and read back.
said "Write this calibration into the vehicle? Nothing is written without your yes."
grep -q "^    PARAM_SET INS_ACCOFFS_X = " "$work/out" || fail "the write-back's PARAM_SETs not shown"
said "cannot hold: misalignment"
said "before: INS_ACCOFFS_X = 0.300000012"
said "read back: all 6 as written"
said "Written: every value was echoed and read back as sent."
said "Verdict:"
[ "$(session_input write_back planned | wc -l)" -eq 6 ] || fail "the planned PARAM_SETs not recorded"
python3 - "$work/v.db" <<'PY' || fail "the write-back step not recorded as written"
import sqlite3, sys
db = sqlite3.connect(sys.argv[1])
rows = db.execute("SELECT outcome FROM steps_done WHERE step_id = 'write_back'").fetchall()
assert rows and rows[-1][0] == "written", rows
PY

# What the wizard showed is what export-cal computes from the session, and what the vehicle holds.
expect 0 "$accelcal" export-cal "$work/v.db" --to "$mav" --procedure "$work/autopilot.toml"
grep "^PARAM_SET" "$work/out" > "$work/export.sets"
stop_bench
python3 - "$work/vehicle.json" "$work/export.sets" <<'PY' || fail "the vehicle does not hold what was shown"
import json, re, sys
params = json.load(open(sys.argv[1]))["params"]
sets = [re.match(r"PARAM_SET (\w+) = (\S+)", l).groups() for l in open(sys.argv[2])]
assert len(sets) == 6, sets
for name, value in sets:
    v = float(value)
    assert abs(params[name] - v) <= 1e-6 * max(1.0, abs(v)), (name, params[name], v)
PY
# A vehicle that does not echo INS_ACCSCAL_X: the write-back stops there and says what was written
# and what not; Enter leaves it so, and the step is recorded as stopped. (The static poses only:
# the turntable adds nothing to what is checked here.)
python3 - "$work/autopilot.toml" "$work/statics.toml" <<'PY'
import sys
text = open(sys.argv[1]).read()
head, *steps = text.split("\n[[step]]")
open(sys.argv[2], "w").write(head + "".join("\n[[step]]" + s for s in steps if 'kind = "turntable"' not in s))
PY
grep -q 'kind = "turntable"' "$work/statics.toml" && fail "statics procedure: a turntable step left"
bench_scenario=  # the default bench
start_bench 20 node "$source_dir/tests/peers/mavlink_vehicle.cjs" --tcp 0 --no-echo INS_ACCSCAL_X
mav="mavlink:tcp:127.0.0.1:$peer_port"
set +e
python3 "$source_dir/tests/e2e/lib/answer_prompts.py" --first BENCH-9 --first tester \
  --when "Write this calibration into the vehicle?=yes" -- \
  "$accelcal" wizard --source "$mav" --bench-control "127.0.0.1:$bench_port" \
  --procedure "$work/statics.toml" --session "$work/stop.db" --plain > "$work/out" 2> "$work/err"
code=$?
set -e
stop_bench
[ "$code" -eq 0 ] || { tail -40 "$work/out" >&2; cat "$work/err" >&2; fail "wizard (no echo) exited $code"; }
said "problem: the write-back stopped: tcp:127.0.0.1:$peer_port: no PARAM_VALUE echoed the PARAM_SET of INS_ACCSCAL_X"
said "written: INS_ACCOFFS_X, INS_ACCOFFS_Y, INS_ACCOFFS_Z"
said "not written: INS_ACCSCAL_Y, INS_ACCSCAL_Z"
said "The vehicle was not fully written: the lines above say what it holds now."
python3 - "$work/stop.db" <<'PY' || fail "the stopped write-back not recorded as stopped"
import sqlite3, sys
db = sqlite3.connect(sys.argv[1])
outcome = db.execute("SELECT outcome FROM steps_done WHERE step_id = 'write_back'").fetchall()[-1][0]
assert outcome.startswith("stopped: ") and "INS_ACCSCAL_X" in outcome, outcome
recorded = db.execute("SELECT value FROM inputs WHERE step_id = 'write_back' AND key = 'outcome'").fetchall()[-1][0]
assert "not written: INS_ACCSCAL_Y, INS_ACCSCAL_Z" in recorded, recorded
PY
echo "vehicle_wizard: ok"

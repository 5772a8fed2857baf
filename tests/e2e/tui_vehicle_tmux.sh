#!/usr/bin/env bash
# Issue 30 in the TUI, driven through tmux (send-keys, capture-pane): a session (static poses) on the
# node-mavlink test vehicle (tests/peers/mavlink_vehicle.cjs, SCALED_IMU after its own
# calibration, 5 % of its frames dropped) behind the virtual bench (lib/remote_bench.bash), from
# the welcome to the write-back: the vehicle's calibration on the welcome's screen, the 1 mG
# resolution beside the noise floor, the vehicle rebooted (SIGUSR1) on a screen past the welcome and
# said as a notice of the source marked [LINK] with its figures on d,
# the write-back's question answered by typing yes, the values echoed and read back, and the
# vehicle holding what the session's export computes. Exit status 0, the terminal restored.
# Usage: bash tui_vehicle_tmux.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source_dir=$2
command -v tmux >/dev/null || { echo "SKIP: tmux not installed"; exit 77; }
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
. "$source_dir/tests/e2e/lib/remote_bench.bash"
. "$source_dir/tests/peers/node_peers.bash"
sock="accelcal_tui_vehicle_$$"  # a private tmux server
tmx() { tmux -L "$sock" "$@"; }
trap 'tmx kill-server 2>/dev/null; stop_bench; rm -rf "$work"' EXIT
screen=""
fail() { echo "FAIL: $*" >&2; [ -n "$screen" ] && printf '%s\n' "--- screen:" "$screen" >&2; exit 1; }
need_node_peers
sed -e 's/^capture_duration_s = 10 /capture_duration_s = 3 /' \
  "$source_dir/procedures/autopilot_imu.toml" > "$work/autopilot.toml"
# The static poses only (what is checked here is the same; the time in CI is not).
python3 - "$work/autopilot.toml" <<'PY'
import sys
head, *steps = open(sys.argv[1]).read().split("\n[[step]]")
open(sys.argv[1], "w").write(head + "".join("\n[[step]]" + s for s in steps if 'kind = "turntable"' not in s))
PY
grep -q 'kind = "turntable"' "$work/autopilot.toml" && fail "statics procedure: a turntable step left"

# A quiet sensor (about 0.9 mG of noise): the vehicle's 1 mG steps are as coarse as its noise, so
# the noise floor is the rounding's as much as the sensor's.
quiet_scenario "$work/quiet.toml"
bench_scenario=$work/quiet.toml
start_bench 20 node "$source_dir/tests/peers/mavlink_vehicle.cjs" --tcp 0 --msg scaled --drop 0.05 \
  --scale 556.8 --bias 32768 \
  --summary "$work/vehicle.json" --param INS_ACCOFFS_X=0.3 --param INS_ACCSCAL_Y=1.03
mav="mavlink:tcp:127.0.0.1:$peer_port"
cat > "$work/run.sh" <<EOS
cd "$work"
"$accelcal" wizard --source "$mav" --bench-control "127.0.0.1:$bench_port" \
  --procedure "$work/autopilot.toml" --session "$work/v.db" 2> "$work/wizard.err"
echo "EXIT=\$? \$(stty -a | grep -o -- ' -\\?icanon') \$(stty -a | grep -o -- ' -\\?echo ')" > "$work/exit"
sleep 60
EOS
tmx new-session -d -s v -x 100 -y 50 "bash '$work/run.sh'"

has() { grep -qF -- "$1" <<< "$screen"; }
asking() { grep -q '^> ' <<< "$screen"; }  # a text field: d would be typed
deadline=$((SECONDS + 280))
welcome=0 serial=0 operator=0 resolution=0 link=0 figures=0 asked=0 written=0 finished=0 rebooted=0
while [ $SECONDS -lt $deadline ]; do
  sleep 0.5
  [ -s "$work/exit" ] && fail "the wizard left before its final screen: $(cat "$work/exit") $(cat "$work/wizard.err")"
  screen=$(tmx capture-pane -p -t v 2>/dev/null || true)
  has "The device's own calibration, as it holds it now:" && has "INS_ACCOFFS: x 0.3" && welcome=1
  has "Limited by the resolution: the readings come in steps of 9.81 counts" && resolution=1
  # d is the figures' key where the keys line offers it so (elsewhere the step's own d, or typed).
  if has "[LINK] The link to the device" && has "d figures" && [ $figures = 0 ] && ! asking; then
    link=1
    tmx send-keys -t v d; sleep 0.5  # the figures, one key away
    screen=$(tmx capture-pane -p -t v 2>/dev/null || true)
    grep -q '^detail   .*\(Hz\|tcp:127\)' <<< "$screen" && figures=1
    tmx send-keys -t v d; continue
  fi
  has "read back: all 6 as written" && written=1
  if has "any key leave"; then finished=1; break; fi
  if has "> Device serial number" && [ $serial = 0 ]; then
    tmx send-keys -t v -l BENCH-9; tmx send-keys -t v Enter; serial=1; continue
  fi
  if has "> Operator" && [ $operator = 0 ]; then
    tmx send-keys -t v -l tester; tmx send-keys -t v Enter; operator=1; continue
  fi
  if has "Type yes to write these values into the vehicle" && [ $asked = 0 ]; then
    has "PARAM_SET INS_ACCOFFS_X = " || fail "the write-back asks without showing its PARAM_SETs"
    tmx send-keys -t v -l yes; tmx send-keys -t v Enter; asked=1; continue
  fi
  # The vehicle reboots on the first screen past the welcome that waits for Enter: the notice comes
  # at a moment the test picks (the lost samples' notices come when the machine's speed says).
  if [ $rebooted = 0 ] && grep -q '^ *Step \([2-9]\|[1-9][0-9]\) of' <<< "$screen" && ! asking \
      && grep -q 'Enter' <<< "$(tail -n 1 <<< "$screen")"; then
    vehicle=$(pgrep -g "$bench_group" -f '^node .*mavlink_vehicle[.]cjs') || fail "the test vehicle's process was not found"
    kill -USR1 $vehicle; rebooted=1
    for _ in $(seq 40); do
      sleep 0.25
      screen=$(tmx capture-pane -p -t v 2>/dev/null || true)
      has "[LINK] The link to the device" && break
    done
    has "[LINK] The link to the device" || fail "the vehicle's reboot was not said on the screen"
    continue
  fi
  # Enter only where the keys line offers it: a capture's screen (and a notice on it) is left alone.
  grep -q 'Enter' <<< "$(tail -n 1 <<< "$screen")" && tmx send-keys -t v Enter 2>/dev/null
done
[ $finished = 1 ] || fail "the session did not reach its final screen"
[ $welcome = 1 ] || fail "the welcome did not show the vehicle's calibration"
[ $resolution = 1 ] || fail "the noise floor did not say the 1 mG steps"
[ $rebooted = 1 ] || fail "the vehicle was never rebooted (no screen past the welcome waited for Enter)"
[ $link = 1 ] || fail "no notice of the source was shown"
[ $figures = 1 ] || fail "d did not show the notice's figures"
[ $asked = 1 ] && [ $written = 1 ] || fail "the write-back was not asked and written (asked $asked, written $written)"
tmx send-keys -t v q
for _ in $(seq 100); do [ -s "$work/exit" ] && break; sleep 0.1; done
line=$(cat "$work/exit" 2>/dev/null || true)
case "$line" in EXIT=0*) ;; *) fail "exit status not 0: $line" ;; esac
grep -q -- ' icanon' <<< "$line" && grep -q -- ' echo' <<< "$line" || fail "terminal not restored: $line"

expect 0 "$accelcal" export-cal "$work/v.db" --to "$mav" --procedure "$work/autopilot.toml"
grep "^PARAM_SET" "$work/out" > "$work/export.sets"
stop_bench
python3 - "$work/vehicle.json" "$work/export.sets" <<'PY' || fail "the vehicle does not hold what the session computes"
import json, re, sys
params = json.load(open(sys.argv[1]))["params"]
sets = [re.match(r"PARAM_SET (\w+) = (\S+)", l).groups() for l in open(sys.argv[2])]
assert len(sets) == 6, sets
for name, value in sets:
    v = float(value)
    assert abs(params[name] - v) <= 1e-6 * max(1.0, abs(v)), (name, params[name], v)
PY
echo "tui_vehicle_tmux: ok"

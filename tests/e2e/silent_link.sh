#!/usr/bin/env bash
# A link that stays connected but sends nothing, or only unreadable lines (issue 17, item 6):
# the line-mode wizard must not hang. A python3 TCP server plays the silent link; the procedure's
# capture timeout is 3 s, and the wizard must give up on the wall clock, say why, and leave at
# the end of its answers. The outer `timeout 60` only turns a hang into a failure (generous: a
# loaded CI machine).
# Usage: bash silent_link.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"

sed -e 's/^capture_timeout_s = 60 /capture_timeout_s = 3 /' \
  "$source_dir/procedures/full_calibration.toml" > "$work/short.toml"
grep -q '^capture_timeout_s = 3 ' "$work/short.toml" || fail "short procedure: no capture_timeout_s"

for mode in silent nan; do
  start_silent_server "$mode" 0
  # Serial, operator, place, gravity, equipment (twice: its example ids are refused once), then
  # Enter to measure the noise floor; then end of input.
  set +e
  printf 'SN1\nme\n\n\n\n\n\n' | timeout 60 "$accelcal" wizard --source "tcp:127.0.0.1:$port" \
    --procedure "$work/short.toml" --session "$work/$mode.db" --plain > "$work/out" 2> "$work/err"
  code=$?
  set -e
  stop_silent_server
  [ "$code" -ne 124 ] || { tail -5 "$work/out" >&2; fail "$mode: the wizard hung on a silent link"; }
  [ "$code" -eq 0 ] || { cat "$work/err" >&2; fail "$mode: the wizard exited $code"; }
  grep -q "problem: no samples for [0-9]* s: the noise floor cannot be measured" "$work/out" \
    || { tail -8 "$work/out" >&2; fail "$mode: no reason given"; }
  grep -q "hint: check the cable or the sample server; Enter measures again, q leaves" "$work/out" \
    || fail "$mode: no hint"
  grep -q "^Saved. Everything accepted is in session" "$work/out" || fail "$mode: not saved and left"
done
echo "silent_link: ok"

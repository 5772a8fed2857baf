#!/usr/bin/env bash
# A record step (the drift and noise records) on a link that falls silent (issue 17, item 6, for
# records): samples come, then the link stays connected and sends nothing readable. The record
# must stop on the wall clock after its silence limit (its step's timeout_s - duration_s: 3 s
# here), say why, keep what it recorded, and the wizard leave at the end of its answers. A
# python3 TCP server plays the link; the outer `timeout 60` only turns a hang into a failure.
# Usage: bash silent_record.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"

sed -e 's/^duration_s = 60 .*/duration_s = 60\ntimeout_s = 63/' \
  "$source_dir/procedures/noise.toml" > "$work/noise.toml"
grep -q '^timeout_s = 63' "$work/noise.toml" || fail "procedure: no timeout_s"

for mode in silent nan; do
  start_silent_server "$mode" 6
  # Serial, operator, place, gravity, Enter for the noise floor, Enter to start the record; end.
  set +e
  printf 'SN1\nme\n\n\n\n\n' | timeout 60 "$accelcal" wizard --source "tcp:127.0.0.1:$port" \
    --procedure "$work/noise.toml" --session "$work/$mode.db" --plain > "$work/out" 2> "$work/err"
  code=$?
  set -e
  stop_silent_server
  [ "$code" -ne 124 ] || { tail -8 "$work/out" >&2; fail "$mode: the wizard hung on a silent link"; }
  [ "$code" -eq 0 ] || { cat "$work/err" >&2; fail "$mode: the wizard exited $code"; }
  grep -q "problem: no samples for [0-9]* s: the record stopped at .* of 1 min 0 s\? *(kept up to its last sample)" "$work/out" \
    || grep -q "problem: no samples for [0-9]* s: the record stopped" "$work/out" \
    || { tail -12 "$work/out" >&2; fail "$mode: no reason given"; }
  grep -q "hint: check the cable or the sample server; Enter goes on with the record" "$work/out" \
    || { tail -12 "$work/out" >&2; fail "$mode: no hint"; }
  grep -q "^Saved. Everything accepted is in session" "$work/out" || fail "$mode: not saved and left"
  # The record is kept: `allan` reads it back (a few seconds of samples, none NaN).
  expect 0 "$accelcal" allan "$work/$mode.db"
  grep -Eq "samples|read" "$work/out" || { cat "$work/out" >&2; fail "$mode: allan of the kept record"; }
done
echo "silent_record: ok"

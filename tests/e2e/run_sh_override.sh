#!/usr/bin/env bash
# scripts/run.sh passes its arguments to `accelcal wizard` and they override its defaults
# (--source sim --speed 20): `./scripts/run.sh --speed 1` once stopped with CLI11's "At Most 1
# required but received 2". ACCELCAL names the program (no setup, no build).
# Usage: run_sh_override.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$(realpath "$1")
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
export HOME=$work XDG_DATA_HOME=$work/data

# The words run.sh passes, seen by a stand-in program.
printf '#!/bin/sh\nprintf "%%s\\n" "$*"\n' > "$work/show_args"
chmod +x "$work/show_args"
args_of() { ACCELCAL=$work/show_args "$source_dir/scripts/run.sh" "$@"; }
[ "$(args_of)" = "wizard --source sim --speed 20" ] || fail "defaults: $(args_of)"
[ "$(args_of --speed 1)" = "wizard --source sim --speed 1" ] || fail "--speed 1: $(args_of --speed 1)"
[ "$(args_of --speed=0 --plain)" = "wizard --source sim --speed=0 --plain" ] || fail "--speed=0: $(args_of --speed=0 --plain)"
[ "$(args_of --source serial:/dev/ttyUSB0@115200)" = "wizard --speed 20 --source serial:/dev/ttyUSB0@115200" ] ||
  fail "--source: $(args_of --source serial:/dev/ttyUSB0@115200)"

# The real program: a whole unattended session at --speed 0, run from another directory.
cd "$work"
set +e
yes '' | ACCELCAL=$accelcal "$source_dir/scripts/run.sh" --speed 0 --plain --session s.db > out 2> err
code=${PIPESTATUS[1]}
set -e
[ "$code" -eq 0 ] || fail "run.sh --speed 0 exited $code: $(cat err)"
grep -q "Calibration complete" out || fail "the session did not end: $(tail -3 out)"
[ -f "$work/s.db" ] || fail "no session where --session said (relative to the caller's directory)"
echo ok

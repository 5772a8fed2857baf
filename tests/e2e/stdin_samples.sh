#!/usr/bin/env bash
# `--source -`: stdin carries the samples, so the wizard's answers come from the terminal
# (/dev/tty), never from the sample stream (issue 17, item 3). Before, `cat rec.txt | accelcal
# wizard --source - --plain` stored sample lines as the device and the operator.
# Usage: bash stdin_samples.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
printf '0 2048 2048 2400\n0.01 2048 2048 2400\n' > "$work/rec.txt"

# No terminal at all (setsid: no controlling terminal): refused with the reason, nothing written.
set +e
setsid -w "$accelcal" wizard --source - --plain --session "$work/none.db" < "$work/rec.txt" \
  > "$work/out" 2> "$work/err"
code=$?
set -e
[ "$code" -eq 1 ] || { cat "$work/out" "$work/err" >&2; fail "no terminal: exited $code, expected 1"; }
grep -q "^accelcal: error: --source - reads the samples from stdin, so the answers must come from a terminal, and this process has none" \
  "$work/err" || { cat "$work/err" >&2; fail "no terminal: reason"; }
[ ! -e "$work/none.db" ] || fail "no terminal: a session was created"

# A terminal (script gives the wizard one): the answers typed there, the samples from stdin.
if command -v script > /dev/null; then
  { printf 'SN-TTY\nAda\n\n\n\nq\n'; sleep 1; } | timeout 60 script -qec \
    "'$accelcal' wizard --source - --plain --session '$work/tty.db' < '$work/rec.txt'" /dev/null \
    > "$work/out" 2>&1 || { tail -20 "$work/out" >&2; fail "terminal: the wizard failed"; }
  expect 0 "$accelcal" sessions "$work"
  grep -Eq '^tty .* SN-TTY +Ada ' "$work/out" || { cat "$work/out" >&2; fail "terminal: device and operator"; }
fi
echo "stdin_samples: ok"

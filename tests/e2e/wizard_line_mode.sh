#!/usr/bin/env bash
# End-to-end: `accelcal wizard --plain` takes every default on the virtual bench (speed 0) and
# completes a whole calibration, printing the report.
# Usage: bash wizard_line_mode.sh ACCELCAL_BINARY SOURCE_DIR DATA_DIR
set -euo pipefail

accelcal=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }

# `yes` gets SIGPIPE when the wizard exits; only the wizard's status counts.
set +e
yes '' | "$accelcal" wizard --source sim --speed 0 --session "$work/s.db" --plain \
  > "$work/out" 2> "$work/err"
code=${PIPESTATUS[1]}
set -e
[[ $code -eq 0 ]] || fail "exit $code: $(cat "$work/err")"
grep -q '19 captures fitted: they agree with one calibration' "$work/out" || fail "the fit did not use 19 captures"
grep -q '^\[24/24\] Done' "$work/out" || fail "the wizard did not reach the end"
grep -q 'Calibration complete' "$work/out" || fail "no completion message"
grep -q 'misalignment (mrad)  yz ' "$work/out" || fail "no misalignment in the summary"
# The statistics are one key away, not on the technician's screens (issue 27, item 9).
! grep -q 'chi2/dof\|NLopt\|condition number' "$work/out" || fail "the fit's statistics on a plain screen"

# d at the fit shows them.
if command -v python3 > /dev/null; then
  printf 'enter_until 19 captures fitted\nsend d\nask parameters (1-sigma):\nenter_until Calibration complete.\n' > "$work/technician"
  timeout 120 python3 "$source_dir/tests/e2e/lib/answer_when_asked.py" "$work/technician" "$work/out3" -- \
    "$accelcal" wizard --source sim --speed 0 --session "$work/d.db" --plain ||
    { tail -20 "$work/out3" >&2; fail "d did not show the fit's statistics"; }
  grep -q 'chi2/dof' "$work/out3" || fail "no statistics on d"
fi
grep -q 'Full calibration: level, 9 prism poses' "$work/out" || fail "the procedure is not named"
# Issue 35: the end of a finished session said "time: session: about 20 s left (estimate)" (the
# report step's reading allowance). Its last time line says the session ends.
last_time=$(grep 'time: ' "$work/out" | tail -1)
[[ $last_time == *"session: this is the last step; the session ends when you continue"* ]] ||
  fail "the last step's time line: $last_time"
if grep -n 'time: ' "$work/out" | tail -1 | grep -q ' left'; then fail "time left at the end: $last_time"; fi

# End of input = save and leave, exit 0.
set +e
printf '\n\n' | "$accelcal" wizard --source sim --speed 0 --session "$work/t.db" --plain \
  > "$work/out2" 2> "$work/err2"
code=$?
set -e
[[ $code -eq 0 ]] || fail "EOF exit $code"
grep -q 'Saved' "$work/out2" || fail "EOF did not save and leave"

# The procedure's former name (seed_calibration.toml, now full_calibration.toml) and its former
# path in the source tree still open it; a session begun under one resumes under the other.
set +e
printf 'q\n' | "$accelcal" wizard --source sim --speed 0 --session "$work/old.db" --plain \
  --procedure seed_calibration.toml > "$work/out4" 2> "$work/err4"
code=$?
set -e
[[ $code -eq 0 ]] || fail "--procedure seed_calibration.toml exit $code: $(cat "$work/err4")"
grep -q 'Full calibration' "$work/out4" || fail "the old name did not open the full calibration"
set +e
printf 'q\n' | (cd "$source_dir" && "$accelcal" wizard --source sim --speed 0 --session "$work/old.db" \
  --plain --procedure procedures/seed_calibration.toml) > "$work/out5" 2> "$work/err5"
code=$?
set -e
[[ $code -eq 0 ]] || fail "the old path exit $code: $(cat "$work/err5")"
grep -q 'Full calibration' "$work/out5" || fail "the old path did not open the full calibration"

# A malformed procedure: exit 1, FILE:LINE on stderr.
printf 'title = "x"\n[sensor]\nnominal_scale_counts_per_mps2 = 34.8\nnominal_bias_counts = 2048\nbogus = 1\n' \
  > "$work/bad.toml"
set +e
"$accelcal" wizard --plain --speed 0 --procedure "$work/bad.toml" < /dev/null > /dev/null 2> "$work/err3"
code=$?
set -e
[[ $code -eq 1 ]] || fail "bad procedure exited $code"
grep -q 'bad.toml:5:' "$work/err3" || fail "no position: $(cat "$work/err3")"

echo "wizard_line_mode: ok"

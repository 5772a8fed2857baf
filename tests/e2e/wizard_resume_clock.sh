#!/usr/bin/env bash
# Issue 12, problem 5: a resumed session's clock went backwards (each run restarted the sample
# clock), so `accelcal export` of it then `accelcal fit` failed ("t = 13.56 s is earlier than
# t = 1017.21 s"). Now the times go on across the resume, with the gap stated, and the export
# fits.
# Usage: bash wizard_resume_clock.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure
# First run: welcome, noise floor, leveling, three poses, then q.
wizard bench_default.toml "$work/s.db" '\n\n\n\n\n\n\n\n\n\n\nq\n'
said "Saved."
wizard bench_default.toml "$work/s.db" ''
said "Resuming session"
said "The session clock goes on at t = "
said "Verdict: PASS"
"$accelcal" export "$work/s.db" -o "$work/c.csv" > /dev/null
"$accelcal" fit "$work/c.csv" -o "$work/fit.json" > "$work/fit.out" 2>&1 || { cat "$work/fit.out" >&2; fail "the export does not fit"; }
# The clock never goes back, and the gap is stated in the session.
grep -v '^#' "$work/c.csv" | tail -n +2 | awk -F, 'NR > 1 && $3 + 0 < last { print "t goes back at row " NR ": " $3 " < " last; exit 1 } { last = $3 + 0 }' ||
  fail "the exported clock goes back"
echo "wizard_resume_clock: ok"

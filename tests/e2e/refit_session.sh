#!/usr/bin/env bash
# Correcting a finished session (issue 27, item 5). Once, after "gravity not established",
# resuming with --latitude 0 still used the standard value without saying the flag was ignored,
# and running the finished session again with --gravity 9.7803 said "Calibration complete (in
# an earlier run): nothing left to do." Now the wizard names the flag it does not use and the
# command that does, and `accelcal refit SESSION --gravity ...` fits the session again in one
# command: the new calibration is the session's result, the earlier one is kept (never replaced
# silently), the report is written again and `accelcal report` says what changed. The wizard
# opened on the finished session asks "Refit it with new inputs?" and does the same (Enter
# leaves the session as it is).
# Usage: bash refit_session.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure
results() { python3 -c 'import sqlite3, sys; print(sqlite3.connect(sys.argv[1]).execute("SELECT count(*) FROM results").fetchone()[0])' "$1"; }
# A lab at the equator that does not know its gravity: the standard value, by default.
wizard clumsy_local_gravity.toml "$work/s.db" ''
said "Verdict: FAIL"
said "gravity not established"
before=$(grep -o "ACC-s-[0-9A-F]\{8\}" "$work/s.report.txt" | head -1)
# A copy, for the refit from the wizard below.
python3 -c 'import sqlite3, sys; sqlite3.connect(sys.argv[1]).backup(sqlite3.connect(sys.argv[2]))' \
  "$work/s.db" "$work/w.db"

# The finished session run again with a gravity flag: the flag is named as not used, the refit
# offered; Enter leaves it as it is.
wizard clumsy_local_gravity.toml "$work/s.db" '' --latitude 0
said "--latitude 0 ignored: this session's gravity was recorded at its welcome (standard); to calibrate it with another: accelcal refit $work/s.db --latitude 0"
said "This session is finished: FAIL in an earlier run."
said "Refit it with new inputs?"
said "Calibration recorded in an earlier run; it does not conform (FAIL)"
[ "$(results "$work/s.db")" -eq 1 ] || fail "Enter at the refit offer recorded a result"

# The correction, in one command.
expect 0 "$accelcal" refit "$work/s.db" --procedure "$work/short.toml" --gravity 9.7803+-0.00001
said "Refitted session $work/s.db (refit 1):"
said "gravity: standard -> 9.7803 +- 1e-05"
said "Verdict: PASS"
said "The earlier calibration is kept in the session (2 in all)"
[ "$(results "$work/s.db")" -eq 2 ] || fail "the earlier result was not kept"
expect 0 "$accelcal" report "$work/s.db"
flat "$work/out" "Result: PASS" || fail "the report is not of the refitted calibration"
flat "$work/out" "refit 1 (" || fail "the report does not list the refit"
flat "$work/out" "gravity: standard -> 9.7803 +- 1e-05" || fail "the report does not say what changed"
flat "$work/out" "1 earlier calibration is kept in the session; this is the latest" ||
  fail "the report does not say an earlier calibration exists"
flat "$work/out" "9.78030 +- 0.00001 m/s^2 (measured)" || fail "the report does not state the new gravity"
after=$(grep -o "ACC-s-[0-9A-F]\{8\}" "$work/s.report.txt" | head -1)
[ -n "$after" ] && [ "$after" != "$before" ] || fail "the report beside the session was not written again"
"$accelcal" report "$work/s.db" --format calibration -o "$work/cal.json" > /dev/null
within_truth 4
# The wizard opened again on the refitted session says the new verdict.
wizard clumsy_local_gravity.toml "$work/s.db" ''
said "Verdict: PASS"
# A value the procedure refuses is refused, and nothing is recorded.
expect 1 "$accelcal" refit "$work/s.db" --procedure "$work/short.toml" --equipment "hammer id 3"
grep -q "is not a piece of equipment" "$work/err" || fail "a wrong equipment answer was not refused with the reason"
[ "$(results "$work/s.db")" -eq 2 ] || fail "a refused refit recorded a result"
expect 1 "$accelcal" refit "$work/nothing.db"

# The same from the wizard: the finished session opened again, the correction typed at its
# offer (a wrong word refused first, with what to type).
wizard clumsy_local_gravity.toml "$work/w.db" 'gravity at the equator\ngravity 9.7803 +- 0.00001\n'
said "refused: gravity:"
said "Refitted (refit 1), the captures fitted again with:"
said "gravity: standard -> 9.7803 +- 1e-05"
said "Verdict: PASS"
said "Calibration complete."
said "The earlier calibration is kept in the session"
[ "$(results "$work/w.db")" -eq 2 ] || fail "the wizard's refit did not keep the earlier result"
flat "$work/w.report.txt" "gravity: standard -> 9.7803 +- 1e-05" || fail "the wizard's refit did not write the report again"
echo "refit_session: ok"

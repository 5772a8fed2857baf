#!/usr/bin/env bash
# A required run the fit leaves out makes the session INCOMPLETE, and the wizard offers to take
# exactly that run again at once (issue 27, items 2 and 8). Once, a turntable run mounted at
# 106 mm when 100 mm was typed passed the live check (inside 10 %), the fit left it out ("it
# disagrees with the other captures"), and the certificate said "Overall: PASS" and "Every step
# of the procedure was done"; the run was not offered again (8 presses of b to reach it).
#  - Offered at the report, named by its radius and speed, and declined (n): the wizard's
#    summary, the report it writes and `accelcal report` later say INCOMPLETE and name the run;
#    the ending is not "Calibration complete" and names the next step.
#  - The wizard run again on that session offers the run first; Enter takes it again (the
#    technician now mounts it as asked): PASS, the run left out superseded.
#  - A new session with Enter everywhere: the run taken again at once, PASS.
# Usage: bash left_out_run.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
command -v python3 >/dev/null || { echo "python3 missing: skipped"; exit 77; }
short_procedure
# The clumsy bench's wrong radius, 106 mm instead of 150: asked for +y radial at 0.10 m.
sed -e 's/^radius_m = 0.15 .*/radius_m = 0.106/' "$source_dir/scenarios/clumsy_wrong_radius.toml" > "$work/r106.toml"
grep -q '^radius_m = 0.106' "$work/r106.toml" || fail "no mounting to change"
offer="The fit left out '+y radial, +z up at 100 mm, 120 rpm' (capture 14)"

# Declined.
printf 'enter_until %s\nsend n\n' "$offer" > "$work/technician"
set +e
timeout 120 python3 "$source_dir/tests/e2e/lib/answer_when_asked.py" "$work/technician" "$work/out" -- \
  "$accelcal" wizard --source sim --speed 0 --scenario "$work/r106.toml" --procedure "$work/short.toml" \
  --session "$work/s.db" --plain
code=$?
set -e
[ "$code" -eq 0 ] || { tail -30 "$work/out" >&2; fail "the declined session did not end (status $code)"; }
said "Left out: capture 14 (+y radial, +z up at 100 mm, 120 rpm): disagrees with the other captures"
said "Enter takes it again now (recommended"
said "Verdict: INCOMPLETE"
said "incomplete: required step '+y radial, +z up at 100 mm, 120 rpm' its capture 14 was left out by the fit"
said "take '+y radial, +z up at 100 mm, 120 rpm' again, mounted as asked"
said "Calibration recorded, but INCOMPLETE"
! grep -q "Calibration complete" "$work/out" || fail "an INCOMPLETE session said 'Calibration complete'"
"$accelcal" report "$work/s.db" > "$work/later.txt"
for report in "$work/s.report.txt" "$work/later.txt"; do
  cp "$report" "$work/report"
  flat "$work/report" "Result: INCOMPLETE" || fail "the report is not INCOMPLETE"
  flat "$work/report" "+y radial, +z up at 100 mm, 120 rpm (tt_y_100, required): its capture 14 was left out by the fit" ||
    fail "the report does not name the run left out"
  ! grep -q "Every step of the procedure was done" "$work/report" || fail "the report says every step was done"
done

# The same session again: the run offered first, taken again on Enter (mounted as asked now); the
# full procedure holds 19 captures (its closing repeat pose), so the retake is capture 20.
wizard bench_default.toml "$work/s.db" ''
said "$offer"
said "taken again: capture 20 replaces capture 14"
said "Verdict: PASS"
said "Calibration complete."
"$accelcal" report "$work/s.db" > "$work/report"
flat "$work/report" "Result: PASS" || fail "the session's report after the run was taken again is not PASS"

# A new session, Enter everywhere: taken again at once.
wizard "$work/r106.toml" "$work/new.db" ''
said "$offer"
said "taken again: capture 20 replaces capture 14"
said "Verdict: PASS"
echo "left_out_run: ok"

#!/usr/bin/env bash
# Issue 12, problem 4: `s` skipped "-x up" without a word, and the report said "17 captures:
# 17 used ... Overall: PASS". Now s asks first (Enter keeps the step), a skipped required step
# is listed and the verdict is INCOMPLETE, in the wizard and in `accelcal report` later.
# A real source with an empty device serial is refused when the procedure requires one.
# Usage: bash clumsy_skip.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure
# Welcome (4), noise floor (1), leveling (3), +z, -z, +x (3): then at -x up, s, Enter (keep it),
# s, s (skip it).
wizard bench_default.toml "$work/s.db" '\n\n\n\n\n\n\n\n\n\n\n\ns\n\ns\ns\n'
said "Skip '-x up'? The procedure requires it: without it the report's verdict is INCOMPLETE."
[ "$(grep -c "Skip '-x up'?" "$work/out")" -eq 2 ] || fail "s did not ask twice"
said "Verdict: INCOMPLETE"
said "missing: -x up (pose_mx, required): skipped"
"$accelcal" report "$work/s.db" > "$work/report"
grep -q "Result: *INCOMPLETE" "$work/report" || fail "report: not INCOMPLETE"
grep -q "\-x up (pose_mx, required): skipped" "$work/report" || fail "report: the skipped step is not named"
grep -q "INCOMPLETE: required step '-x up' skipped" "$work/report" || fail "report: no reason"
"$accelcal" report "$work/s.db" --format json | jq -e '.verdict == "INCOMPLETE" and .session_gaps.steps[0].id == "pose_mx"'   > /dev/null || fail "report json"

# A real source (a recording replayed): the procedure requires the serial; Enter is refused.
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" --recording -o "$work/rec.txt" > /dev/null 2>&1 ||
  printf '0 2048 2048 2390\n0.01 2048 2048 2390\n' > "$work/rec.txt"
set +e
printf '\n\nBOARD-7\n\nq\n' | "$accelcal" wizard --source "file:$work/rec.txt" --procedure "$work/short.toml"   --session "$work/r.db" --plain > "$work/out" 2>&1
set -e
said "refused: this procedure needs the device's serial number (on its label): type it"
"$accelcal" sessions "$work/r.db" > "$work/sessions"
grep -q "BOARD-7" "$work/sessions" || fail "the typed serial was not recorded"
echo "clumsy_skip: ok"

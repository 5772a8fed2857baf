#!/usr/bin/env bash
# A certificate is PASS only with identified equipment (issue 27, item 3). Once "id RUL-01
# (example) ... state its certificate" went through to a signed-looking PASS. A bench whose
# uncertainties are good but whose items keep the procedure's example ids: the welcome refuses
# them once, naming them and what to type; Enter again goes on and the verdict is INCOMPLETE,
# naming them; the same bench with its ids given at the welcome: PASS, nothing refused.
# Usage: bash equipment_identified.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure
# The virtual lab's uncertainties and calibrations, the procedure's example ids.
sed -e 's/^equipment = "ruler id SIM.*/equipment = "ruler u 0.03 cal C-1; turntable u 0.02 cal C-2"/' \
  "$source_dir/scenarios/bench_default.toml" > "$work/examples.toml"
grep -q '^equipment = "ruler u 0.03' "$work/examples.toml" || fail "no lab equipment to change"
wizard "$work/examples.toml" "$work/ex.db" ''
said "Equipment: ruler RUL-01 (example) 0.03 mm (cal C-1); turntable TT-01 (example) 0.02 %"
said "refused: this procedure issues a certificate, and ruler RUL-01 (example), turntable TT-01 (example), level LVL-01 (example), prism PR-01 (example) are not your bench's own"
[ "$(grep -c "not your bench's own" "$work/out")" -eq 1 ] || fail "the example ids were refused more than once"
said "Verdict: INCOMPLETE"
said "incomplete: equipment not identified: ruler RUL-01 (example), turntable TT-01 (example), level LVL-01 (example), prism PR-01 (example)"
"$accelcal" report "$work/ex.db" > "$work/report"
flat "$work/report" "Result: INCOMPLETE" || fail "the report is not INCOMPLETE"
flat "$work/report" "RUL-01 (example): not identified" || fail "the traceability does not say the ruler is not identified"
! grep -q "Conforms:" "$work/report" || fail "the certificate says it conforms"
# Identified at the welcome (device, operator, place, gravity by default; then the equipment).
wizard "$work/examples.toml" "$work/id.db" '\n\n\n\nruler id RUL-7; turntable id TT-3; level id LVL-2; prism id PR-9\n'
said "Verdict: PASS"
! grep -q "not your bench's own" "$work/out" || fail "identified equipment was refused"
"$accelcal" report "$work/id.db" > "$work/report"
flat "$work/report" "ruler: steel ruler 300 mm and compass, id RUL-7, u = 0.03 mm" ||
  fail "the edit did not apply over the offered equipment"
flat "$work/report" "Result: PASS" || fail "the identified bench's report is not PASS"
echo "equipment_identified: ok"

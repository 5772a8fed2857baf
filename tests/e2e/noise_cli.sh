#!/usr/bin/env bash
# End to end: `accelcal noise` on three noise sessions of one device on three days (made by
# accelcal_make_session --noise with known bias offsets and the default bench's white noise),
# checked against the simulated truth; text and JSON; a calibration; a recording file; and the
# failure paths (unknown device, one day only). Called by ctest as:
#   noise_cli.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
: "$data"
make_session=$(dirname "$accelcal")/accelcal_make_session
source "$src/tests/e2e/lib/common.bash"
procedure=$src/procedures/noise.toml

# near VALUE TRUTH TOL: |VALUE - TRUTH| <= TOL
near() { awk -v v="$1" -v t="$2" -v e="$3" 'BEGIN { d = v - t; if (d < 0) d = -d; exit !(d <= e) }'; }
check() {  # check NAME VALUE TRUTH TOL
  near "$2" "$3" "$4" || fail "$1 = $2, expected $3 +- $4"
}

mkdir -p "$work/sessions" "$work/one"
# Bias offsets (counts) per day: x 0, 1, 2 (std 1, range 2); y 0, 0, -2 (std 1.1547, range 2);
# z 0, -1, 0 (std 0.57735, range 1).
"$make_session" "$work/sessions/d1.db" --noise "$procedure" SN-E2E 2026-03-01 0,0,0 101
"$make_session" "$work/sessions/d2.db" --noise "$procedure" SN-E2E 2026-03-02 1,0,-1 102
"$make_session" "$work/sessions/d3.db" --noise "$procedure" SN-E2E 2026-03-04 2,-2,0 103
"$make_session" "$work/sessions/other.db" --noise "$procedure" SN-OTHER 2026-03-01 0,0,0 104
"$make_session" "$work/sessions/cal.db"   # a calibration session (another procedure)

# JSON: per-axis std and density against the truth. White noise sigma (1.5, 1.5, 1.7) counts
# plus the rounding's 1/12 count^2: std sqrt(sigma^2 + 1/12); density N = std / sqrt(100 Hz).
expect 0 "$accelcal" noise SN-E2E --sessions-dir "$work/sessions" --format json -o "$work/n.json"
j() { jq -r "$1" "$work/n.json"; }
[ "$(j '.records | length')" = 3 ] || fail "expected 3 records"
[ "$(j '.unit')" = counts ] || fail "unit $(j .unit)"
[ "$(j '[.records[].date] | join(" ")')" = "2026-03-01 2026-03-02 2026-03-04" ] || fail "dates"
for axis in x y z; do
  sigma=1.5; [ $axis = z ] && sigma=1.7
  std=$(awk -v s=$sigma 'BEGIN { print sqrt(s * s + 1 / 12) }')
  density=$(awk -v s="$std" 'BEGIN { print s / sqrt(100) }')
  for r in 0 1 2; do
    check "record $r $axis std" "$(j ".records[$r].axes.$axis.std")" "$std" "$(awk -v s="$std" 'BEGIN { print 0.05 * s }')"
    check "record $r $axis density" "$(j ".records[$r].axes.$axis.density")" "$density" "$(awk -v s="$density" 'BEGIN { print 0.10 * s }')"
    [ "$(j ".records[$r].axes.$axis.normality.verdict")" = normal ] || fail "record $r $axis not normal"
  done
done
[ "$(j '.records[0].spectrum.frequency_hz | length')" -le 200 ] || fail "spectrum too long"
# Repeatability: the offsets' std and range (each mean carries ~0.02 counts of noise).
check "x std of means" "$(j '.repeatability.std_of_means[0]')" 1 0.1
check "y std of means" "$(j '.repeatability.std_of_means[1]')" 1.1547 0.1
check "z std of means" "$(j '.repeatability.std_of_means[2]')" 0.57735 0.1
check "x max-min" "$(j '.repeatability.max_minus_min[0]')" 2 0.1
check "z max-min" "$(j '.repeatability.max_minus_min[2]')" 1 0.1
[ "$(j '.repeatability.days')" = 3 ] || fail "days"
[ "$(j '.warnings | length')" = 0 ] || fail "unexpected warnings: $(j '.warnings')"

# Text: the table fits 80 columns and names the repeatability.
expect 0 "$accelcal" noise SN-E2E --sessions-dir "$work/sessions"
grep -q 'Turn-on bias repeatability (day-to-day change of the mean), 3 day' "$work/out" || { cat "$work/out"; fail "text: repeatability"; }
grep -Eq '^  x +[0-9.]+ +1\.[45][0-9]* +0\.1[45][0-9]* +normal' "$work/out" || { cat "$work/out"; fail "text: x row"; }
awk 'length($0) > 80 { exit 1 }' "$work/out" || fail "text wider than 80 columns"

# With a calibration: m/s^2, z reads gravity.
"$accelcal" report "$work/sessions/cal.db" --format calibration -o "$work/cal.json" >/dev/null
expect 0 "$accelcal" noise SN-E2E --sessions-dir "$work/sessions" --calibration "$work/cal.json" --format json -o "$work/n.json"
[ "$(j '.unit')" = "m/s^2" ] || fail "calibrated unit"
check "calibrated z mean" "$(j '.records[0].axes.z.mean')" 9.80665 0.05
# The calibrated session itself gives the same (the one calibration-input rule).
expect 0 "$accelcal" noise SN-E2E --sessions-dir "$work/sessions" --calibration "$work/sessions/cal.db" --format json -o "$work/n_db.json"
cmp -s <(jq -S 'del(.generated_utc)' "$work/n.json") <(jq -S 'del(.generated_utc)' "$work/n_db.json") ||
  fail "noise --calibration: the session and its calibration file differ"

# One day only: the result says the repeatability needs three days.
mv "$work/sessions/other.db" "$work/one/"
expect 0 "$accelcal" noise SN-OTHER --sessions-dir "$work/one"
grep -q 'needs records on 3 different days; have 1' "$work/out" || { cat "$work/out"; fail "one day"; }
grep -q 'not computed' "$work/out" || { cat "$work/out"; fail "one day: figure"; }

# Unknown device: a clear message listing the devices that have noise sessions.
expect 1 "$accelcal" noise SN-NOPE --sessions-dir "$work/sessions"
grep -q 'no noise record of device SN-NOPE' "$work/err" || { cat "$work/err"; fail "unknown device message"; }
grep -q 'SN-E2E (3 sessions)' "$work/err" || { cat "$work/err"; fail "unknown device: list"; }
expect 1 "$accelcal" noise SN-E2E --sessions-dir "$work/nowhere"
grep -q 'cannot list sessions' "$work/err" || { cat "$work/err"; fail "missing directory"; }
expect 2 "$accelcal" noise SN-E2E --format xml --sessions-dir "$work/sessions"
expect 1 "$accelcal" noise --sessions-dir "$work/sessions"

# Recording files: undated, each taken as its own day.
expect 0 "$accelcal" record --source sim --speed 0 --duration 60 -o "$work/rec.txt"
expect 0 "$accelcal" noise --record "$work/rec.txt" --format json -o "$work/n.json"
[ "$(j '.records[0].date')" = null ] || fail "file record has a date"
check "file x std" "$(j '.records[0].axes.x.std')" 1.5275 0.08
printf '0 1 2 3\n0.01 1 2 x\n' > "$work/bad.txt"
expect 1 "$accelcal" noise --record "$work/bad.txt"
grep -q 'bad.txt:2' "$work/err" || { cat "$work/err"; fail "bad recording: position"; }
echo "noise_cli: ok"

#!/usr/bin/env bash
# Real files from the field (issue 14), end to end through the binary: test files of the shapes
# other people's loggers write, made by tests/e2e/lib/field_gen.py from the physics alone
# (independent of accelcal's code), each calibrated from the command line and its numbers
# checked against the truth by lib/check_truth.py (every fitted parameter within 4 sigma).
# Also the capture set's `up` column (issue 13 item 4): a capture on the wrong face is named.
# Called by ctest as: field_files.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2
source "$(dirname "$0")/lib/common.bash"
command -v python3 >/dev/null || { echo "python3 missing: skipped"; exit 77; }
gen="python3 $src/tests/e2e/lib/field_gen.py"
check="python3 $src/tests/e2e/lib/check_truth.py"

# Six faces: bias and scale, the misalignments held at 0 and said so.
$gen captures --poses six --seed 3 -o "$work/six.csv" --truth "$work/six.json"
expect 0 "$accelcal" fit "$work/six.csv" --no-diagnose -o "$work/six_cal.json"
grep -q "held" "$work/out" || fail "six faces: held angles not stated"
grep -qi "tilted" "$work/out" || fail "six faces: no advice to add tilted poses"
$check "$work/six_cal.json" "$work/six.json" --held a_yz,a_zy,a_zx >"$work/chk" || { cat "$work/chk"; fail "six faces: numbers"; }

# Eleven poses that the old rank test refused for some seeds (issue 17 item 1): all seeds fit.
for seed in 1 4 7 8; do
  $gen captures --poses p11 --seed $seed --samples 300 -o "$work/p11.csv" --truth "$work/p11.json"
  expect 0 "$accelcal" fit "$work/p11.csv" --no-diagnose -o "$work/p11_cal.json"
  $check "$work/p11_cal.json" "$work/p11.json" >"$work/chk" || { cat "$work/chk"; fail "p11 seed $seed: numbers"; }
done

# A plain recording of 40 hand-placed near-face poses: uncertainties cover the truth.
$gen recording --poses near40 --seed 5 --style plain -o "$work/plain.txt" --truth "$work/plain.json"
expect 0 "$accelcal" fit --recording "$work/plain.txt" --no-diagnose -o "$work/plain_cal.json"
$check "$work/plain_cal.json" "$work/plain.json" >"$work/chk" || { cat "$work/chk"; fail "near40: numbers"; }

# RealSense style: m/s^2, t printed with two decimals at 200 Hz (stamps repeat): repaired, said so.
$gen recording --poses near40 --seed 6 --rate 200 --style realsense -o "$work/rs.csv" --truth "$work/rs.json"
expect 0 "$accelcal" fit --recording "$work/rs.csv" --unit m/s^2 --no-diagnose -o "$work/rs_cal.json"
grep -q "repeated time stamp" "$work/out" || fail "realsense: the time repair not said"
$check "$work/rs_cal.json" "$work/rs.json" --mcounts >"$work/chk" || { cat "$work/chk"; fail "realsense: numbers"; }
grep -q '"unit": "m/s^2"' "$work/rs_cal.json" || fail "realsense: reading unit not in the calibration"
# Without the repair the repeated stamps are an error, as before.
expect 1 "$accelcal" fit --recording "$work/rs.csv" --unit m/s^2 --no-repair-time --no-diagnose -o "$work/x.json"

# Gyro first: the header names the columns; and the same with --columns and no header.
$gen recording --poses near40 --seed 7 --style gyro-first -o "$work/gf.txt" --truth "$work/gf.json"
expect 0 "$accelcal" fit --recording "$work/gf.txt" --no-diagnose -o "$work/gf_cal.json"
grep -q "gx" "$work/out" || fail "gyro-first: ignored columns not reported"
$check "$work/gf_cal.json" "$work/gf.json" >"$work/chk" || { cat "$work/chk"; fail "gyro-first: numbers"; }
tail -n +2 "$work/gf.txt" >"$work/gf_noheader.txt"
expect 0 "$accelcal" fit --recording "$work/gf_noheader.txt" --columns t,-,-,-,ax,ay,az --no-diagnose -o "$work/gf2_cal.json"
$check "$work/gf2_cal.json" "$work/gf.json" >"$work/chk" || { cat "$work/chk"; fail "gyro-first --columns: numbers"; }

# Arduino MPU-6050 CSV: metadata lines, a header, no time column (100 Hz known).
$gen recording --poses near40 --seed 8 --style mpu6050 -o "$work/mpu.csv" --truth "$work/mpu.json"
expect 0 "$accelcal" fit --recording "$work/mpu.csv" --skip-rows 4 --rate-hz 100 --no-diagnose -o "$work/mpu_cal.json"
$check "$work/mpu_cal.json" "$work/mpu.json" >"$work/chk" || { cat "$work/chk"; fail "mpu6050: numbers"; }
# Without --rate-hz it says that the file has no time column.
expect 1 "$accelcal" fit --recording "$work/mpu.csv" --skip-rows 4 --no-diagnose -o "$work/x.json"
grep -qi "rate" "$work/err" || fail "mpu6050 without a rate: the error does not point to --rate-hz"

# The `up` column: a capture taken on the wrong face (+z asked, -z measured) is named.
$gen captures --poses p12 --seed 2 --samples 300 -o "$work/p12.csv" --truth "$work/p12.json"
awk -F, 'BEGIN{OFS=","} $1=="1" && $2=="static" {$11="0.000000 0.000000 -1.000000"} {print}' "$work/p12.csv" >"$work/wrong.csv"
expect 0 "$accelcal" fit "$work/p12.csv" --no-diagnose -o "$work/p12_cal.json"
! grep -q "requested up" "$work/out" || fail "up column: a warning on the right poses"
expect 0 "$accelcal" fit "$work/wrong.csv" --no-diagnose -o "$work/wrong_cal.json"
grep -q "capture 1 ('pose 1'): the measured up" "$work/out" || fail "up column: the wrong face not named"
echo ok

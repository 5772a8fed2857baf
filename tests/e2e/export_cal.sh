#!/usr/bin/env bash
# End to end: `accelcal export-cal` on a calibration made by simulate + fit, every target's file
# checked (the C header compiled and run against `accelcal apply`, the parameter files parsed
# and their values recomputed from the calibration), a session as input, and the failure paths.
# Called by ctest as: export_cal.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
source "$(dirname "$0")/lib/common.bash"
: "$data"
make_session=$(dirname "$accelcal")/accelcal_make_session

expect 0 "$accelcal" simulate "$src/scenarios/bench_default.toml" -o "$work/c.csv"
expect 0 "$accelcal" fit "$work/c.csv" --no-diagnose -q -o "$work/cal.json"
expect 0 "$accelcal" simulate "$src/scenarios/effects_demo.toml" -o "$work/fx.csv"
expect 0 "$accelcal" fit "$work/fx.csv" -q -o "$work/fx.json"
printf '%s %s %s %s\n' 1 2051 2040 2400  2 1700 2050 2048  3 2400 1800 2100  4 2048 2300 1690  5 1990 2001 2222 >"$work/raw.txt"

# c-header: compiled with the system C compiler; its output matches `accelcal apply` (which
# prints 6 decimals) on the same raws, for the base model and with the quadratic effect.
cat >"$work/main.c" <<'C'
#define ACCELCAL_REAL double
#include <stdio.h>
#include "accel_cal.h"
int main(void) {
  double t, x, y, z, a[3];
  while (scanf("%lf %lf %lf %lf", &t, &x, &y, &z) == 4) {
    accelcal_correct(x, y, z, a);
    printf("%g %.6f %.6f %.6f\n", t, a[0], a[1], a[2]);
  }
  return 0;
}
C
for cal in cal fx; do
  expect 0 "$accelcal" export-cal "$work/$cal.json" --to c-header -o "$work/accel_cal.h" --device BOARD-7
  grep -q "c-header holds the whole calibration" "$work/out" || fail "c-header statement ($cal)"
  grep -q "device BOARD-7" "$work/accel_cal.h" || fail "device not in the header"
  cc -std=c99 -Wall -Wextra -Werror -pedantic -I"$work" -o "$work/prog" "$work/main.c" -lm || fail "header does not compile ($cal)"
  "$work/prog" <"$work/raw.txt" >"$work/c_out.txt"
  "$accelcal" apply "$work/$cal.json" <"$work/raw.txt" >"$work/apply_out.txt" 2>/dev/null
  paste "$work/c_out.txt" "$work/apply_out.txt" | awk '{ for (i = 2; i <= 4; ++i) { d = $i - $(i + 4); if (d < 0) d = -d; if (d > 2e-6) exit 1 } } END { if (NR != 5) exit 1 }' ||
    { paste "$work/c_out.txt" "$work/apply_out.txt"; fail "c-header and apply disagree ($cal)"; }
done
grep -q "quadratic_nonlinearity" "$work/accel_cal.h" || fail "quadratic not in the header"
grep -q "note: effect radius_offset is not exported" "$work/out" || fail "radius offset not noted"

# ardupilot: needs the nominal scale; with the procedure's [sensor] (34.8 counts per m/s^2,
# zero-g 2048) the values are (b - 2048) / 34.8 and 34.8 / k.
expect 1 "$accelcal" export-cal "$work/cal.json" --to ardupilot
grep -q "needs the sensor's nominal scale" "$work/err" || fail "nominal scale not asked for"
expect 0 "$accelcal" export-cal "$work/cal.json" --to ardupilot --procedure "$src/procedures/full_calibration.toml" -o "$work/a.param"
grep -q "^cannot hold: misalignment .* costs up to .* m/s^2" "$work/out" || fail "misalignment loss not stated"
python3 - "$work/cal.json" "$work/a.param" <<'PY' || fail "ArduPilot values"
import json, sys
cal = json.load(open(sys.argv[1]))
p = dict(l.strip().split(",") for l in open(sys.argv[2]) if l.strip() and not l.startswith("#"))
assert len(p) == 6, p
for i, ax in enumerate("XYZ"):
    assert abs(float(p["INS_ACCOFFS_" + ax]) - (cal["bias_counts"][i] - 2048) / 34.8) < 1e-6, p
    assert abs(float(p["INS_ACCSCAL_" + ax]) - 34.8 / cal["scale_counts_per_mps2"][i]) < 1e-7, p
PY

# px4: QGroundControl's tab-separated format; CAL_ACC0_ID cannot be known (said) unless given.
expect 0 "$accelcal" export-cal "$work/cal.json" --to px4 --nominal-scale-counts-per-mps2 34.8 --nominal-bias-counts 2048 -o "$work/p.params"
grep -q "^cannot hold: CAL_ACC0_ID" "$work/out" || fail "CAL_ACC0_ID not stated"
[ "$(grep -cP '^1\t1\tCAL_ACC0_[XYZ](OFF|SCALE)\t-?[0-9.e-]+\t9$' "$work/p.params")" -eq 6 ] || { cat "$work/p.params"; fail "px4 lines"; }
expect 0 "$accelcal" export-cal "$work/cal.json" --to px4 --nominal-scale-counts-per-mps2 34.8 34.8 34.8 --nominal-bias-counts 2048 --px4-device-id 1310988
grep -qP '^1\t1\tCAL_ACC0_ID\t1310988\t6$' "$work/out" || fail "device id line (to stdout)"
grep -q "cannot hold: misalignment" "$work/err" || fail "statements not on stderr without -o"

# kalibr: refuses without figures; from an Allan file in counts (worst axis, divided by scale).
expect 1 "$accelcal" export-cal "$work/cal.json" --to kalibr
grep -q "give --allan" "$work/err" || fail "kalibr refusal"
cat >"$work/allan.json" <<'J'
{"unit": "counts", "rate_hz": 100,
 "axes": {"x": {"noise_density": 0.05, "random_walk": 0.002}, "y": {"noise_density": 0.09, "random_walk": 0.001},
          "z": {"noise_density": 0.06, "random_walk": null}}}
J
expect 0 "$accelcal" export-cal "$work/cal.json" --to kalibr --allan "$work/allan.json" -o "$work/imu.yaml"
grep -q "^cannot hold: the gyroscope's noise" "$work/out" || fail "gyroscope not stated"
python3 - "$work/cal.json" "$work/imu.yaml" <<'PY' || fail "Kalibr values"
import json, sys
k = json.load(open(sys.argv[1]))["scale_counts_per_mps2"]
y = {}
for line in open(sys.argv[2]):
    line = line.split("#")[0].strip()
    if line:
        key, value = line.split(": ")
        y[key] = value
assert set(y) == {"accelerometer_noise_density", "accelerometer_random_walk", "rostopic", "update_rate"}, y
assert abs(float(y["accelerometer_noise_density"]) - 0.09 / k[1]) < 1e-12, y
assert abs(float(y["accelerometer_random_walk"]) - 0.002 / k[0]) < 1e-12, y
assert y["update_rate"] == "100.0" and y["rostopic"] == "/imu0", y
PY
expect 0 "$accelcal" export-cal "$work/cal.json" --to kalibr --noise-density 0.002 --random-walk 3e-5 --rate-hz 200
grep -q "^accelerometer_noise_density: 0.002 " "$work/out" || fail "kalibr from options"

# csv: header, the nine parameters, gravity and residual; RFC 4180 parsed.
expect 0 "$accelcal" export-cal "$work/cal.json" --to csv -o "$work/p.csv"
python3 - "$work/cal.json" "$work/p.csv" <<'PY' || fail "CSV values"
import csv, json, sys
cal = json.load(open(sys.argv[1]))
rows = list(csv.reader(open(sys.argv[2], newline="")))
assert rows[0] == ["name", "value", "sigma", "unit"] and len(rows) == 12, rows
r = {row[0]: row for row in rows[1:]}
assert float(r["bias_y"][1]) == cal["bias_counts"][1] and float(r["bias_y"][2]) == cal["uncertainty"]["bias_counts"][1]
assert float(r["a_zx"][1]) == cal["misalignment_rad"]["zx"] and r["a_zx"][3] == "rad"
PY

# A session as input: its device and date go into the file.
"$make_session" "$work/s.db" --device SIM-0042 --date 2025-03-01T14:05:09.000Z
expect 0 "$accelcal" export-cal "$work/s.db" --to c-header
grep -q "device SIM-0042, calibrated 2025-03-01T14:05:09.000Z" "$work/out" || fail "session origin"

# Failure paths: one clear line, exit 1 (bad usage: 2).
expect 1 "$accelcal" export-cal "$work/missing.json" --to csv
grep -q "missing.json" "$work/err" || fail "missing file not named"
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "more than one line on stderr"
expect 1 "$accelcal" export-cal "$work/c.csv" --to csv
grep -q "c.csv" "$work/err" || fail "not-a-calibration not named"
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "more than one line on stderr"
"$make_session" "$work/half.db" --no-result
expect 1 "$accelcal" export-cal "$work/half.db" --to csv
grep -q "has no calibration yet" "$work/err" || fail "session without result"
expect 2 "$accelcal" export-cal "$work/cal.json" --to matlab
grep -q "\-\-to" "$work/err" || fail "unknown target not explained"
expect 1 "$accelcal" export-cal "$work/cal.json" --to px4 --nominal-scale-counts-per-mps2 34.8 34.8
grep -q "one value (all axes) or three" "$work/err" || fail "two values accepted"
echo ok

#!/usr/bin/env bash
# End to end: `accelcal allan` on virtual-bench records with known noise (the sensor of
# scenarios/drift_demo.toml, white noise 1.5 counts at 100 Hz, with a random walk of
# 0.2 counts/sqrt(s) and no bias instability, so that one hour shows two decades of the walk),
# recorded by `accelcal record` from the simulator:
#   - the noise density (N) within 10 % and the random walk (K) within 30 % of the truth;
#   - the same record with 60 s cut out: one gap listed with its 6000 missing samples, the
#     figures still right;
#   - counts vs m/s^2 with a calibration; errors (missing file, malformed line) named.
# Called by ctest as: allan_cli.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
: "$data"
source "$src/tests/e2e/lib/common.bash"

near() { awk -v v="$1" -v t="$2" -v e="$3" 'BEGIN { d = v - t; if (d < 0) d = -d; exit !(d <= e) }'; }
check() {  # check NAME VALUE TRUTH RELATIVE_TOL
  near "$2" "$3" "$(awk -v t="$3" -v r="$4" 'BEGIN { print t * r }')" ||
    fail "$1 = $2, expected $3 within $4 relative"
}

sed -e 's/^bias_random_walk_counts_per_sqrt_s = .*/bias_random_walk_counts_per_sqrt_s = [0.2, 0.2, 0.2]/' \
    -e 's/^bias_instability_counts = .*/bias_instability_counts = [0, 0, 0]/' \
    "$src/scenarios/drift_demo.toml" > "$work/scenario.toml"
grep -q "^bias_random_walk_counts_per_sqrt_s = \[0.2" "$work/scenario.toml" || fail "scenario not derived"
# 1 hour at 100 Hz, as fast as the simulator goes.
expect 0 "$accelcal" record --source sim --scenario "$work/scenario.toml" --speed 0 \
  --duration 3600 -o "$work/rec.txt"
expect 0 "$accelcal" allan "$work/rec.txt" -o "$work/allan.json"
grep -q "noise density" "$work/out" || fail "no read-off table on stdout"
j() { jq -r "$1" "$work/allan.json"; }
[ "$(j .unit)" = counts ] || fail "unit $(j .unit)"
check rate_hz "$(j .rate_hz)" 100 1e-9
[ "$(j '.gaps | length')" = 0 ] || fail "gaps in a continuous record"
# Truth: N = sqrt(1.5^2 + 1/12) / sqrt(100 Hz) (the ADC's rounding adds 1/12 count^2 of white
# noise), K = 0.2 counts/sqrt(s).
n_true=$(awk 'BEGIN { print sqrt(1.5 * 1.5 + 1 / 12) / 10 }')
for axis in x y z; do
  check "$axis noise density" "$(j ".axes.$axis.noise_density")" "$n_true" 0.10
  check "$axis random walk" "$(j ".axes.$axis.random_walk")" 0.2 0.30
  [ "$(j ".axes.$axis.tau_s | length")" = "$(j ".axes.$axis.adev_hi | length")" ] || fail "curve lengths"
  # Each point lies inside its own confidence band.
  [ "$(jq "[.axes.$axis | range(0; .adev | length) as \$i | select(.adev_lo[\$i] > .adev[\$i] or .adev_hi[\$i] < .adev[\$i])] | length" "$work/allan.json")" = 0 ] ||
    fail "$axis: a point outside its band"
done

# The same record with 60 s lost (t in [1000, 1060)).
awk '$1 < 1000 || $1 >= 1060' "$work/rec.txt" > "$work/gap.txt"
expect 0 "$accelcal" allan "$work/gap.txt" -o "$work/gap.json"
[ "$(jq '.gaps | length' "$work/gap.json")" = 1 ] || fail "the gap is not listed"
[ "$(jq '.gaps[0].missing_samples' "$work/gap.json")" = 6000 ] || fail "missing samples $(jq '.gaps[0].missing_samples' "$work/gap.json")"
check "gap: x noise density" "$(jq .axes.x.noise_density "$work/gap.json")" "$n_true" 0.10
grep -q "6000 missing in 1 gaps" "$work/out" || fail "the gap is not in the text"

# With a calibration: m/s^2, the counts figures divided by the scale (34.62 counts per m/s^2 on x).
"$accelcal" simulate "$src/scenarios/bench_default.toml" -o "$work/cal_set.csv" >/dev/null
"$accelcal" fit "$work/cal_set.csv" -o "$work/cal.json" >/dev/null
head -n 200000 "$work/rec.txt" > "$work/short.txt"
expect 0 "$accelcal" allan "$work/short.txt" --calibration "$work/cal.json" -o "$work/si.json"
[ "$(jq -r .unit "$work/si.json")" = "m/s^2" ] || fail "unit with a calibration"
check "x noise density in m/s^2" "$(jq .axes.x.noise_density "$work/si.json")" \
  "$(awk -v n="$n_true" 'BEGIN { print n / 34.62 }')" 0.10

# Kalibr's imu.yaml: the largest axis's N in m/s^2/sqrt(Hz); needs the calibration.
expect 0 "$accelcal" allan "$work/short.txt" --calibration "$work/cal.json" --kalibr "$work/imu.yaml"
worst=$(jq '[.axes[].noise_density] | max' "$work/si.json")
got=$(awk '/^accelerometer_noise_density:/ { print $2 }' "$work/imu.yaml")
check "kalibr noise density" "$got" "$worst" 1e-6
grep -q '^update_rate: 100' "$work/imu.yaml" || fail "kalibr update_rate: $(cat "$work/imu.yaml")"
grep -q '^accelerometer_random_walk: [0-9]' "$work/imu.yaml" || fail "kalibr random walk"
expect 1 "$accelcal" allan "$work/short.txt" --kalibr "$work/imu.yaml"
grep -q "Kalibr wants m/s^2" "$work/err" || fail "kalibr without calibration: $(cat "$work/err")"

# Errors: a missing file; a malformed line named by file and line.
expect 1 "$accelcal" allan "$work/none.txt"
grep -q "cannot open" "$work/err" || fail "missing file: $(cat "$work/err")"
{ head -n 50 "$work/rec.txt"; echo "1e9 1 x 3"; } > "$work/bad.txt"
expect 1 "$accelcal" allan "$work/bad.txt"
grep -q "bad.txt:51:" "$work/err" || fail "malformed line not named: $(cat "$work/err")"
echo "allan_cli: ok"

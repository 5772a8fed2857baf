#!/usr/bin/env bash
# End to end through the binary: simulate -> fit -> apply, and the exit codes and messages of
# the failure paths. Called by ctest as: fit_cli.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
source "$(dirname "$0")/lib/common.bash"

# The happy path.
expect 0 "$accelcal" simulate "$src/scenarios/bench_default.toml" -o "$work/c.csv" --truth "$work/truth.json"
expect 0 "$accelcal" fit "$work/c.csv" -o "$work/cal.json"
grep -q "fit converged: 18 captures" "$work/out" || fail "fit summary missing"
grep -q "gravity: 9.80665 +- 0.02309 m/s^2 (standard gravity, not the local value)" "$work/out" || fail "gravity not stated"
grep -q '"format": "accelcal-calibration/1"' "$work/cal.json" || fail "calibration file format"
grep -q '"effects": \[\]' "$work/cal.json" || fail "effects not listed"

# The effects demo: the diagnosis names the injected effects and the file lists them; apply
# applies the sensor's own (quadratic) and notes the bench's (radius offset).
expect 0 "$accelcal" simulate "$src/scenarios/effects_demo.toml" -o "$work/fx.csv"
expect 0 "$accelcal" fit "$work/fx.csv" -o "$work/fx.json"
grep -q "+ quadratic_nonlinearity" "$work/out" || fail "quadratic not named"
grep -q "+ radius_offset" "$work/out" || fail "radius offset not named"
grep -q '"name": "quadratic_nonlinearity"' "$work/fx.json" || fail "effect not in the file"
printf '0 2051 2040 2400\n' | "$accelcal" apply "$work/fx.json" >"$work/applied" 2>"$work/err"
grep -q "not applied to readings: radius_offset" "$work/err" || fail "radius offset not noted"
expect 0 "$accelcal" fit "$work/fx.csv" --no-diagnose -o "$work/base.json"
grep -q '"effects": \[\]' "$work/base.json" || fail "--no-diagnose still added effects"

# Gravity from a location is stated in the output and the file.
expect 0 "$accelcal" fit "$work/c.csv" --latitude -34.9 --altitude 43 -q -o "$work/cal2.json"
[ ! -s "$work/out" ] || fail "--quiet printed something"
grep -q '"source": "wgs84"' "$work/cal2.json" || fail "wgs84 gravity not recorded"

# apply: a static pose's raw mean comes out near g.
printf '# raw\n0 2051 2040 2400\n' | "$accelcal" apply "$work/cal.json" >"$work/applied"
grep -q '^# raw$' "$work/applied" || fail "comment not passed through"
[ "$(grep -vc '^#' "$work/applied")" -eq 1 ] || fail "apply output"

# A malformed row: exit 1, one line naming file, line and column.
sed '5s/^\([0-9]*\),static,\([^,]*\),[^,]*/\1,static,\2,12x/' "$work/c.csv" >"$work/bad.csv"
expect 1 "$accelcal" fit "$work/bad.csv"
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "more than one line on stderr"
grep -q "bad.csv:5:[0-9]*: column 'ax': '12x' is not a number" "$work/err" || { cat "$work/err"; fail "error text"; }

# Too few captures: refused with the reason (changed with issue 14: six suffice for bias and scale).
head -n 4003 "$work/c.csv" >"$work/few.csv"
expect 1 "$accelcal" fit "$work/few.csv"
grep -q "no calibration: 4 usable captures; a calibration needs at least 6" "$work/err" || { cat "$work/err"; fail "underdetermined text"; }

# Bad usage: exit 2.
expect 2 "$accelcal" fit
expect 2 "$accelcal" fit "$work/c.csv" --gravity 9.8 --latitude 10
expect 2 "$accelcal" fit "$work/c.csv" --recording "$work/c.csv"
expect 2 "$accelcal" nonsense
# A missing input file is bad input, as for every command (issue 15: it was 2, without the
# "accelcal: error:" prefix, while `report missing.db` was 1 with it).
expect 1 "$accelcal" fit "$work/missing.csv"
grep -q "^accelcal: error: no such file: $work/missing.csv$" "$work/err" || { cat "$work/err"; fail "missing file message"; }
# A value that is surely a unit mistake: the job fails, saying why.
expect 1 "$accelcal" fit "$work/c.csv" --gravity 980.665
grep -q "gravity: 980.665 looks like Gal (cm/s^2): in m/s^2 that is 9.80665" "$work/err" || fail "gravity unit message"

# apply with a damaged calibration file.
head -c 200 "$work/cal.json" >"$work/broken.json"
expect 1 "$accelcal" apply "$work/broken.json" </dev/null
grep -q "broken.json:[0-9]*:[0-9]*: not valid JSON" "$work/err" || fail "broken calibration message"

# The real recording (tests/data/imu_tk).
expect 0 "$accelcal" fit --recording "$data/imu_tk/xsens_acc.mat" --gravity 9.81744 -o "$work/imu.json"
grep -q "static intervals: 38 found" "$work/out" || fail "imu_tk intervals"

# --help and --version.
expect 0 "$accelcal" --version
grep -q "^accelcal [0-9]" "$work/out" || fail "version"
# A knock during a static capture: left out with its reason, unless the check is turned off.
cp "$src/scenarios/bench_default.toml" "$work/bump.toml"
printf '\n[[effects.bump]]\ncapture = 2\nat_s = 4.0\npeak_mps2 = 3.0\nduration_s = 0.05\n' >>"$work/bump.toml"
expect 0 "$accelcal" simulate "$work/bump.toml" -o "$work/bump.csv"
expect 0 "$accelcal" fit "$work/bump.csv" -o "$work/bump.json"
grep -q "fit converged: 17 captures" "$work/out" || fail "bumped capture not left out"
grep -q '"reason": "not still: .*spike: ' "$work/bump.json" || fail "stability reason not in the file"
expect 0 "$accelcal" fit "$work/bump.csv" --no-stability-check
grep -q "fit converged: 18 captures" "$work/out" || fail "--no-stability-check"

# Issue 17 item 2: a mistyped radius or speed is never fitted silently. In the default scenario
# capture 10 is the x-radial run at 0.05 m, 120 rpm (columns: capture,kind,t,ax,ay,az,temp_c,
# radius_m,rpm,label,up_axis).
retype() {  # FILE RADIUS RPM: capture 10's stated radius and speed
  awk -F, -v OFS=, -v r="$2" -v w="$3" '$1 == 10 && $2 == "turntable" { $8 = r; $9 = w } { print }' \
    "$work/c.csv" >"$1"
}
# 0.07 m typed for 0.05: the run does not match its readings; left out with the reason, in the
# output and in the file, and the rest calibrates.
retype "$work/r7.csv" 0.07 120
expect 0 "$accelcal" fit "$work/r7.csv" -o "$work/r7.json"
grep -q "fit converged: 17 captures" "$work/out" || { cat "$work/out"; fail "mistyped radius not left out"; }
grep -q "does not match the run" "$work/out" || fail "mistyped radius: no reason in the output"
grep -q '"reason": "the stated radius or speed does not match the run: .*0.07 m' "$work/r7.json" ||
  fail "mistyped radius: no reason in the file"
# The same without the up_axis column's values: found by leave-one-out instead.
awk -F, -v OFS=, 'NR > 3 && $2 == "turntable" { $NF = "" } { print }' "$work/r7.csv" >"$work/r7n.csv"
expect 0 "$accelcal" fit "$work/r7n.csv" -o "$work/r7n.json"
grep -q "fit converged: 17 captures" "$work/out" || { cat "$work/out"; fail "leave-one-out did not leave the run out"; }
grep -q '"reason": "disagrees with the other captures' "$work/r7n.json" || fail "leave-one-out reason"
grep -q 'capture 10 was left out' "$work/r7n.json" || fail "leave-one-out warning in the file"
# Radius and speed swapped: implausible, left out with the reason.
retype "$work/swap.csv" 120 0.05
expect 0 "$accelcal" fit "$work/swap.csv" -o "$work/swap.json"
grep -q "fit converged: 17 captures" "$work/out" || fail "swapped radius and speed not left out"
grep -q "are the radius and the speed swapped" "$work/swap.json" || fail "swap reason"
# Three runs 40 % off, no mounting: more than can be left out; no calibration, exit 1, named.
awk -F, -v OFS=, 'NR > 3 && $2 == "turntable" { $NF = ""; if ($1 == 10 || $1 == 13 || $1 == 16) $8 = $8 * 1.4 } { print }' \
  "$work/c.csv" >"$work/bad3.csv"
expect 1 "$accelcal" fit "$work/bad3.csv" -o "$work/bad3.json"
grep -q "no calibration: the captures disagree with each other" "$work/err" || { cat "$work/err"; fail "refusal text"; }
[ ! -e "$work/bad3.json" ] || fail "a refused fit wrote a calibration file"

for sub in fit apply simulate; do
  expect 0 "$accelcal" "$sub" --help
  grep -q "Example" "$work/out" || fail "$sub --help has no example"
done
echo "fit_cli: all checks passed"

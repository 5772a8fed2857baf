#!/usr/bin/env bash
# CTest: the independent physics bench exercised once. A clean capture set of the seed plan
# (tests/physics/physics_bench.h) through the real `accelcal fit`; the nine parameters must come
# back within 4 sigma of the truth (sigma as the calibration file reports it).
# Called by ctest as: clean_fit.sh ACCELCAL ACCELCAL_PHYSGEN
set -euo pipefail
accelcal=$1 physgen=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$physgen" generate --plan seed --case clean --seed 1 -o "$work/set.csv" --truth "$work/truth.json"
[ "$(grep -c ',static,\|,turntable,' "$work/set.csv")" -eq 18000 ] || fail "expected 18 x 1000 rows"
"$accelcal" fit "$work/set.csv" --gravity 9.80665 -o "$work/cal.json" >"$work/out" 2>"$work/err" ||
  { cat "$work/err" >&2; fail "accelcal fit failed on a clean set"; }
grep -q "fit converged: 18 captures" "$work/out" || { cat "$work/out"; fail "fit summary"; }
line=$("$physgen" compare "$work/truth.json" "$work/cal.json")
echo "adopted, wrong, named, chi2/dof, z of bias_x..a_zx, effect z: $line"
names=(bias_x bias_y bias_z scale_x scale_y scale_z a_yz a_zy a_zx)
IFS=$'\t' read -r -a f <<<"$line"
for k in 0 1 2 3 4 5 6 7 8; do
  z=${f[$((4 + k))]}
  awk -v z="$z" 'BEGIN { exit !(z ~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/ && z + 0 < 4 && z + 0 > -4) }' ||
    fail "${names[$k]} is $z sigma from the truth"
done
echo "ok: the nine parameters within 4 sigma"

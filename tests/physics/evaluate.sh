#!/usr/bin/env bash
# Many-seed evaluation of `accelcal fit` on the independent physics bench (tests/physics).
#
#   tests/physics/evaluate.sh [--seeds N] [--plan seed|rich] [--cases "clean cubic ..."]
#                             [--build DIR] [-j JOBS] [--keep DIR [--keep-sets]]
#                             [--gen-args "..."] [--fit-args "..."]
#
# For each case (default: clean, each in-library effect alone, each out-of-library effect alone)
# and each seed 1..N (default 50): accelcal_physgen generates a capture set and its truth,
# `accelcal fit SET -o cal.json` fits it (diagnosis on), and `accelcal_physgen compare` scores
# the calibration against the truth: the effects adopted (cal.json "effects"[].name), whether one
# is wrong (not the injected effect), and (est - truth) / sigma of the nine parameters (sigma
# from cal.json "uncertainty"). `accelcal_physgen tally` prints the tables. With --keep DIR the
# per-seed lines stay in DIR/results.tsv, each seed's truth, calibration and fit output in
# DIR/CASE.SEED/ (and its capture set with --keep-sets: 1.4 MB each on the seed plan).
# --gen-args go to every `accelcal_physgen generate` (e.g. "--turntable-s 60"), --fit-args to
# every `accelcal fit`.
#
# Binaries: DIR/accelcal and DIR/accelcal_physgen (default: build/ of this checkout).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
build=$here/../../build
seeds=50
plan=seed
cases="clean quadratic temperature_bias temperature_scale bias_drift radius_offset rpm_scale size_effect cubic cross tilt asym_scale bias_jump turntable_bias bias_walk settling flicker"
jobs=2
keep=
keep_sets=
gen_args=
fit_args=
while [ $# -gt 0 ]; do
  case $1 in
    --seeds) seeds=$2; shift 2 ;;
    --plan) plan=$2; shift 2 ;;
    --cases) cases=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    -j) jobs=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    --keep-sets) keep_sets=1; shift ;;
    --gen-args) gen_args=$2; shift 2 ;;
    --fit-args) fit_args=$2; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "evaluate.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done

accelcal=$(cd "$build" && pwd)/accelcal
physgen=$(cd "$build" && pwd)/accelcal_physgen
for b in "$accelcal" "$physgen"; do
  [ -x "$b" ] || { echo "evaluate.sh: $b not built" >&2; exit 2; }
done

if [ -n "$keep" ]; then
  mkdir -p "$keep"
  work=$(cd "$keep" && pwd)
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi

# One seed of one case: prints one tab-separated line (accelcal_physgen tally's input).
run_one() {
  local case=$1 seed=$2 d="$work/$1.$2"
  mkdir -p "$d"
  # shellcheck disable=SC2086
  "$physgen" generate --plan "$plan" --case "$case" --seed "$seed" $gen_args \
    -o "$d/set.csv" --truth "$d/truth.json"
  local g
  g=$(sed -n 's/.*"gravity_mps2": \([0-9.eE+-]*\).*/\1/p' "$d/truth.json")
  # shellcheck disable=SC2086
  if "$accelcal" fit "$d/set.csv" --gravity "$g" -q $fit_args -o "$d/cal.json" >"$d/out" 2>"$d/err"; then
    printf '%s\t%s\tok\t%s\n' "$case" "$seed" "$("$physgen" compare "$d/truth.json" "$d/cal.json")"
  else
    printf '%s\t%s\tfail\t%s\n' "$case" "$seed" "$(head -n 1 "$d/err" | tr '\t' ' ')"
  fi
  if [ -z "$keep" ]; then rm -rf "$d"; elif [ -z "$keep_sets" ]; then rm -f "$d/set.csv"; fi
}
export -f run_one
export work physgen accelcal plan gen_args fit_args keep keep_sets

start=$(date +%s)
for c in $cases; do
  for s in $(seq 1 "$seeds"); do printf '%s %s\n' "$c" "$s"; done
done | xargs -P "$jobs" -n 2 bash -c 'run_one "$0" "$1"' >"$work/results.unsorted"
# Cases in the order asked, seeds in order.
: >"$work/results.tsv"
for c in $cases; do
  awk -F'\t' -v c="$c" '$1 == c' "$work/results.unsorted" | sort -t$'\t' -k2,2n >>"$work/results.tsv"
done
rm -f "$work/results.unsorted"

echo "accelcal_physgen evaluation: plan $plan, $seeds seeds per case, $(date -u +%Y-%m-%dT%H:%MZ)," \
  "$(( $(date +%s) - start )) s"
echo "accelcal: $accelcal ($("$accelcal" --version 2>/dev/null | head -n 1))"
[ -z "$gen_args" ] || echo "generator arguments: $gen_args"
[ -z "$fit_args" ] || echo "fit arguments: $fit_args"
echo
"$physgen" tally "$work/results.tsv"

#!/usr/bin/env bash
# CTest physics.effects_small (issue 13 item 2): the many-seed evaluation of tests/physics/README.md
# in small, on fixed seeds of the independent bench. Every seed must:
# - clean: adopt no effect;
# - cubic, cross, tilt (now in the library): name the injected effect and nothing else;
# - asym_scale, bias_jump, turntable_bias (effects no library has): adopt no effect (the
#   conclusion is "no effect of the library explains them"), or refuse with a reason.
# The numbers over 50+ seeds per case are in tests/physics/README.md (evaluate.sh).
# Called by ctest as: effects_small.sh ACCELCAL ACCELCAL_PHYSGEN
set -euo pipefail
accelcal=$1 physgen=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# case, seed, generator arguments; prints compare's line (or "fail") to stdout
run() {
  local case=$1 seed=$2 args=$3 d="$work/$1.$2"
  mkdir -p "$d"
  # shellcheck disable=SC2086
  "$physgen" generate --plan seed --case "$case" --seed "$seed" $args -o "$d/set.csv" --truth "$d/truth.json"
  if "$accelcal" fit "$d/set.csv" --gravity 9.80665 -q -o "$d/cal.json" >"$d/out" 2>"$d/err"; then
    "$physgen" compare "$d/truth.json" "$d/cal.json"
  else
    echo "fail"
  fi
}

for seed in 1 2; do
  line=$(run clean "$seed" "")
  [ "$(cut -f1 <<<"$line")" = "-" ] || fail "clean seed $seed adopted: $line"
  echo "ok   clean (seed $seed): nothing adopted"
  for c in cubic cross "tilt --turntable-s 300"; do
    read -r name args <<<"$c"
    line=$(run "$name" "$seed" "${args:-}")
    [ "$line" != fail ] || fail "$name seed $seed: fit refused"
    [ "$(cut -f2 <<<"$line")" = 0 ] && [ "$(cut -f3 <<<"$line")" = 1 ] ||
      fail "$name seed $seed: adopted '$(cut -f1 <<<"$line")'"
    echo "ok   $name (seed $seed): named $(cut -f1 <<<"$line"), effect parameters within $(cut -f14 <<<"$line") sigma"
  done
  for name in asym_scale bias_jump turntable_bias; do
    line=$(run "$name" "$seed" "")
    [ "$line" = fail ] || [ "$(cut -f2 <<<"$line")" = 0 ] ||
      fail "$name seed $seed: a library effect adopted for an effect outside it: '$(cut -f1 <<<"$line")'"
    echo "ok   $name (seed $seed): $( [ "$line" = fail ] && echo refused || echo "adopted '$(cut -f1 <<<"$line")'")"
  done
done

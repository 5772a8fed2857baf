#!/usr/bin/env bash
# Line mode through the real binary (issue 15): "?" prints what the step expects and asks again;
# a speed typed at the radius sets the speed; "0,05" is a radius; after a refused plan the speed
# is asked again with the procedure's speed as the default, never the refused one; blanks are
# the default. Usage: line_mode_entries.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; cat "$work/out" >&2; exit 1; }

# The seed procedure cut to its first turntable step (50 mm, 120 rpm).
seed="$src/procedures/full_calibration.toml"
{ sed '/^\[\[step\]\]/,$d' "$seed"
  awk 'BEGIN { RS = ""; ORS = "\n\n" }
    $0 ~ "\\[\\[step\\]\\]\nid = \"tt_x_050\"" { sub(/^[^[]*\[\[step\]\]/, "[[step]]"); print }' "$seed"
} > "$work/tt.toml"

# Welcome: "?" then five defaults (the last the equipment) (one of them blanks); radius: a speed, "?", a decimal comma;
# speed: the default (600 rpm, refused), then q.
printf '?\n\n   \n\n\n\n600 rpm\n?\n0,05\n\nq\n' |
  "$accelcal" wizard --source sim --speed 0 --plain --procedure "$work/tt.toml" --session "$work/l.db" \
  > "$work/out" 2>&1 || fail "exit status $?"
squeezed=$(tr -s ' \n' ' ' < "$work/out")
has() { grep -qF -- "$1" <<<"$squeezed" || fail "not said: $1"; }
has "help: Step: Welcome."
has "serial number, from its label"
has "(empty line) accept"
has "Speed set to 600 rpm; now the radius."
has "Type the distance from the turntable's spin axis"
has "Table speed (e.g. 120 rpm, 2 rps or 2 Hz, 12.57 rad/s) [600 rpm]>"
has "refused: 600 rpm at 0.05 m gives 20.1 g on the radial axis"
has "lower the speed or the radius Table speed (e.g. 120 rpm, 2 rps or 2 Hz, 12.57 rad/s) [120 rpm]>"
has "Saved."
grep -q "unknown unit" "$work/out" && fail "unknown unit"
[ "$(grep -c "Device serial number" "$work/out")" -eq 2 ] || fail "the question was not asked again after the help"
echo ok

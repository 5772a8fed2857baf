#!/usr/bin/env bash
# End to end: `accelcal history` on sessions of one device made on different dates with known
# changes of the true sensor (accelcal_make_session, built beside accelcal): listed in date
# order with the right moves, flagged where they exceed 3 sigmas; another device kept apart;
# an unknown device refused with the list of known ones.
# Called by ctest as: history_cli.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
source "$(dirname "$0")/lib/common.bash"
: "$src" "$data"
make_session=$(dirname "$accelcal")/accelcal_make_session

d=$work/sessions
mkdir -p "$d"
# Names out of date order on purpose. January: as built; March: bias x up 3 counts (a seasonal
# shift); June: the same bias and a_zx up 5 mrad (the board was remounted).
"$make_session" "$d/b.db" --device DEV-A --date 2025-01-10T09:00:00.000Z
"$make_session" "$d/c.db" --device DEV-A --date 2025-03-10T09:00:00.000Z --bias-offset-counts 3,0,0
"$make_session" "$d/a.db" --device DEV-A --date 2025-06-10T09:00:00.000Z --bias-offset-counts 3,0,0 --misalignment-offset-rad 0,0,0.005
"$make_session" "$d/other.db" --device DEV-B --date 2025-02-01T09:00:00.000Z
"$make_session" "$d/open.db" --device DEV-A --date 2025-04-01T09:00:00.000Z --no-result

expect 0 "$accelcal" history DEV-A --sessions-dir "$d" --format json
python3 - "$work/out" <<'PY' || fail "history json"
import json, sys
h = json.load(open(sys.argv[1]))
cals = h["calibrations"]
assert [c["session"] for c in cals] == ["b", "c", "a"], [c["session"] for c in cals]
assert h["sessions_without_calibration"] == 1
assert all(p["delta"] is None for p in cals[0]["parameters"].values())
march, june = cals[1]["parameters"], cals[2]["parameters"]
assert abs(march["bias_x"]["delta"] - 3.0) < 0.05 and march["bias_x"]["changed"], march["bias_x"]
assert [n for n, p in march.items() if p["changed"]] == ["bias_x"], march
assert abs(june["a_zx"]["delta"] - 0.005) < 5e-4 and june["a_zx"]["changed"], june["a_zx"]
assert abs(june["bias_x"]["delta"]) < 0.05 and not june["bias_x"]["changed"], june["bias_x"]
assert abs(june["a_zx"]["n_sigmas"] - abs(june["a_zx"]["delta"]) / june["a_zx"]["sigma_combined"]) < 1e-9
PY

expect 0 "$accelcal" history DEV-A --sessions-dir "$d"
grep -q "^device DEV-A: 3 calibration(s) in $d (1 session(s) without a calibration not shown)$" "$work/out" || { cat "$work/out"; fail "text header"; }
# Date order in the text too, and the flags.
[ "$(grep -E '^20[0-9-]+ [0-9:]+ UTC  session' "$work/out" | awk '{print $5}' | tr '\n' ' ')" = "b c a " ] || fail "text order"
grep -Eq '^  bias_x .* \+3(\.0[0-9]*)? .* changed$' "$work/out" || { cat "$work/out"; fail "bias_x move"; }
grep -q "^  changed: bias_x$" "$work/out" || fail "march summary"
grep -q "^  changed: a_zx$" "$work/out" || fail "june summary"

# Unknown device: exit 1, the known devices listed.
expect 1 "$accelcal" history DEV-Z --sessions-dir "$d"
grep -q "no session of device DEV-Z in $d; devices there: DEV-A, DEV-B" "$work/err" || { cat "$work/err"; fail "unknown device message"; }
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "more than one line on stderr"
expect 1 "$accelcal" history DEV-A --sessions-dir "$work/nowhere"
grep -q "cannot list sessions in $work/nowhere" "$work/err" || { cat "$work/err"; fail "missing directory message"; }
# The default directory comes from XDG_DATA_HOME.
mkdir -p "$work/xdg/accelcal"
cp -r "$d" "$work/xdg/accelcal/sessions"
XDG_DATA_HOME=$work/xdg expect 0 "$accelcal" history DEV-B
grep -q "^device DEV-B: 1 calibration(s)" "$work/out" || fail "default directory"
echo ok

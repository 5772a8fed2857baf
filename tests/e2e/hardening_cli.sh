#!/usr/bin/env bash
# End to end: issue 17's hardening through the real binary. Inputs given as pipes are read once
# (item 9); a calibration that cannot give finite outputs, or holds 1e999, is refused at read
# with the file and field named and no library text (items 7, 11); text that is not UTF-8
# never stops a JSON output (item 7).
# Called by ctest as: hardening_cli.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
source "$(dirname "$0")/lib/common.bash"
: "$data"

no_library_text() { ! grep -q "json.exception\|what()" "$work/err" || fail "library text shown: $(cat "$work/err")"; }

expect 0 "$accelcal" simulate "$src/scenarios/bench_default.toml" -o "$work/c.csv"
expect 0 "$accelcal" fit "$work/c.csv" --no-diagnose -q -o "$work/cal.json"

# Item 9: a calibration given as <(cat cal.json) and a recording as <(cat rec.txt).
expect 0 "$accelcal" report <(cat "$work/cal.json")
grep -q "CALIBRATION REPORT" "$work/out" || fail "report on a pipe printed no report"
expect 0 "$accelcal" export-cal <(cat "$work/cal.json") --to csv -o "$work/cal.csv"
grep -q "bias_x" "$work/cal.csv" || fail "export-cal on a pipe wrote no csv"
awk 'BEGIN { srand(7); for (i = 0; i < 3000; ++i) printf "%.3f %.2f %.2f %.2f\n", i / 100, 2048 + 3 * (rand() - 0.5), 2040 + 3 * (rand() - 0.5), 2400 + 3 * (rand() - 0.5) }' >"$work/rec.txt"
expect 0 "$accelcal" allan "$work/rec.txt" --rate-hz 100
cp "$work/out" "$work/allan_file.txt"
expect 0 "$accelcal" allan <(cat "$work/rec.txt") --rate-hz 100
grep -q "3000 samples" "$work/out" || fail "allan on a pipe: $(head -5 "$work/out")"

# Items 7 and 11: a number beyond a double, and a scale that makes every output infinite.
python3 - "$work" <<'PY'
import json, sys
w = sys.argv[1]
text = open(w + "/cal.json").read()
c = json.loads(text)
c["scale_counts_per_mps2"][0] = 1e-320
json.dump(c, open(w + "/tiny.json", "w"), indent=2)
open(w + "/huge.json", "w").write(text.replace(repr(c["bias_counts"][1]), "1e999", 1))
PY
expect 1 "$accelcal" report "$work/huge.json"
grep -q "huge.json:[0-9]*:[0-9]*: .*1e999 is beyond a double's range" "$work/err" || fail "1e999: $(cat "$work/err")"
no_library_text
for cmd in "report $work/tiny.json" "export-cal $work/tiny.json --to c-header"; do
  # shellcheck disable=SC2086
  expect 1 "$accelcal" $cmd
  grep -q "tiny.json.*would calibrate to an infinite value" "$work/err" || fail "$cmd: $(cat "$work/err")"
done
echo "0 2050 2040 2060" >"$work/raw1.txt"
expect 1 "$accelcal" apply "$work/tiny.json" <"$work/raw1.txt"
grep -q "tiny.json.*would calibrate to an infinite value" "$work/err" || fail "apply: $(cat "$work/err")"
[ ! -s "$work/out" ] || fail "apply printed a value: $(cat "$work/out")"

# Item 12: a folder as a file source is refused with the reason, not "ended, 0 samples".
mkdir "$work/folder"
expect 1 "$accelcal" record --source "file:$work/folder" -o "$work/r.txt" -q
grep -q "is a folder" "$work/err" || fail "record file:DIR: $(cat "$work/err")"

# Item 12: a full disk (/dev/full) is reported with its reason, never exit 0 nor an empty file.
expect 1 "$accelcal" record --source "file:$work/rec.txt" -o /dev/full -q
grep -q "No space left on device" "$work/err" || fail "record on a full disk: $(cat "$work/err")"
expect 1 "$accelcal" simulate "$src/scenarios/bench_default.toml" -o /dev/full
grep -q "No space left on device" "$work/err" || fail "simulate on a full disk: $(cat "$work/err")"
[ -c /dev/full ] || fail "/dev/full was replaced"

# Item 7: a label with a Latin-1 byte: the fit writes its calibration file (valid UTF-8, the
# byte as U+FFFD) instead of failing with a library's text after "converged".
sed 's/,z up,/,z up \xF1,/' "$work/c.csv" >"$work/latin1.csv"
grep -q $'z up \xF1' "$work/latin1.csv" || fail "the test's label was not made"
expect 0 "$accelcal" fit "$work/latin1.csv" --no-diagnose -q -o "$work/latin1.json"
no_library_text
python3 -c 'import json, sys; c = json.load(open(sys.argv[1], encoding="utf-8")); assert any(x["label"] == "z up \ufffd" for x in c["captures"])' "$work/latin1.json" ||
  fail "the calibration file is not UTF-8 or lost the label"

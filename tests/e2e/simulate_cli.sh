#!/usr/bin/env bash
# End-to-end: `accelcal simulate` on the shipped scenarios.
# Usage: bash simulate_cli.sh ACCELCAL_BINARY SOURCE_DIR DATA_DIR
set -euo pipefail

accelcal=$1
source_dir=$2
source "$(dirname "$0")/lib/common.bash"

# Data rows of a capture set: every line that is neither a comment nor the header.
data_rows() { grep -v '^#' "$1" | tail -n +2 | wc -l; }

header='capture,kind,t,ax,ay,az,temp_c,radius_m,rpm,label,up_axis'

# The default bench: 18 captures x 10 s x 100 Hz.
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" -o "$work/default.csv" \
  --truth "$work/truth.json"
[[ $(head -n 1 "$work/default.csv") == '# accelcal capture set' ]] || fail "first line"
[[ $(sed -n 2p "$work/default.csv") == '# adc_range_counts = 0,4095' ]] || fail "adc range line"
[[ $(grep -v '^#' "$work/default.csv" | head -n 1) == "$header" ]] || fail "header row"
[[ $(data_rows "$work/default.csv") -eq 18000 ]] || fail "default: $(data_rows "$work/default.csv") rows"
[[ $(cut -d, -f1 "$work/default.csv" | grep -v '^#' | tail -n +2 | uniq | wc -l) -eq 18 ]] \
  || fail "captures not contiguous"
grep -q '"bias_counts"' "$work/truth.json" || fail "truth lacks bias_counts"
grep -q '"misalignment_rad"' "$work/truth.json" || fail "truth lacks misalignment_rad"

# Standard output (no -o, and -o -) gives the same bytes as the file; --seed changes them.
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" > "$work/stdout.csv"
cmp -s "$work/default.csv" "$work/stdout.csv" || fail "stdout differs from -o FILE"
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" -o - > "$work/dash.csv"
cmp -s "$work/default.csv" "$work/dash.csv" || fail "-o - differs from -o FILE"
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" --seed 99 -o "$work/seed.csv"
! cmp -s "$work/default.csv" "$work/seed.csv" || fail "--seed did not change the output"

# The effects demo: same plan, so the same row count.
"$accelcal" simulate "$source_dir/scenarios/effects_demo.toml" -o "$work/effects.csv"
[[ $(data_rows "$work/effects.csv") -eq 18000 ]] || fail "effects_demo row count"

# A continuous recording: 60 s quiet start + 8 x (4 s move + 10 s hold) at 100 Hz.
"$accelcal" simulate "$source_dir/scenarios/hand_recording.toml" --recording -o "$work/rec.txt"
[[ $(grep -vc '^#' "$work/rec.txt") -eq 17200 ]] || fail "recording rows"
[[ $(grep -v '^#' "$work/rec.txt" | head -n 1 | wc -w) -eq 5 ]] || fail "recording columns"
# Streamed in chunks (issue 18): standard output gets the very same bytes as the file, the file
# is renamed into place whole (no PATH.tmp left), and a longer record (17 200 rows is four
# chunks of 4096 and a rest) still has every row once, in order.
"$accelcal" simulate "$source_dir/scenarios/hand_recording.toml" --recording -o - > "$work/rec_stdout.txt"
cmp -s "$work/rec.txt" "$work/rec_stdout.txt" || fail "recording: stdout and file differ"
[[ ! -e "$work/rec.txt.tmp" ]] || fail "recording: rec.txt.tmp left behind"
grep -v '^#' "$work/rec.txt" | awk 'NR > 1 && !($1 > prev) { bad = 1 } { prev = $1 } END { exit bad }' ||
  fail "recording: t not increasing across chunks"

# A recording of a plan with turntable runs is refused (exit 1, one line).
set +e
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" --recording -o "$work/x" 2> "$work/err"
code=$?
set -e
[[ $code -eq 1 ]] || fail "--recording with turntable captures exited $code"
[[ $(wc -l < "$work/err") -eq 1 ]] || fail "stderr: $(cat "$work/err")"
[[ ! -e "$work/x" && ! -e "$work/x.tmp" ]] || fail "a refused recording left a file behind"

# A scenario that does not exist: exit 1, one line on stderr naming it.
set +e
"$accelcal" simulate "$work/no_such.toml" -o "$work/x.csv" 2> "$work/err"
code=$?
set -e
[[ $code -eq 1 ]] || fail "missing scenario exited $code"
[[ $(wc -l < "$work/err") -eq 1 ]] || fail "missing scenario stderr: $(cat "$work/err")"
grep -q 'no_such.toml' "$work/err" || fail "stderr does not name the file"

# A malformed scenario: exit 1, FILE:LINE:COLUMN on stderr.
printf '[sensor]\nbias_counts = [1, 2, 3]\nscale_counts_per_mps2 = [1, 1, 1]\nnoise_counts = [1, -1, 1]\n' \
  > "$work/bad.toml"
set +e
"$accelcal" simulate "$work/bad.toml" 2> "$work/err" > /dev/null
code=$?
set -e
[[ $code -eq 1 ]] || fail "bad scenario exited $code"
grep -q 'bad.toml:4:' "$work/err" || fail "no position: $(cat "$work/err")"

# Bad usage: exit 2.
set +e
"$accelcal" simulate > /dev/null 2>&1; code_missing=$?
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" --no-such-flag > /dev/null 2>&1
code_flag=$?
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" --seed abc > /dev/null 2>&1
code_seed=$?
set -e
[[ $code_missing -eq 2 ]] || fail "missing scenario argument exited $code_missing"
[[ $code_flag -eq 2 ]] || fail "unknown flag exited $code_flag"
[[ $code_seed -eq 2 ]] || fail "bad --seed exited $code_seed"

# Help says what it does and gives an example.
help=$("$accelcal" simulate --help)
grep -q 'virtual-bench scenario' <<< "$help" || fail "help does not say what simulate does"
grep -q 'accelcal simulate bench_default' <<< "$help" || fail "help has no example"
# The example's form: a shipped scenario named by its name alone, from any directory.
(cd "$work" && "$accelcal" simulate bench_default --seed 7 -o by_name.csv 2> /dev/null) ||
  fail "simulate bench_default failed"
"$accelcal" simulate "$source_dir/scenarios/bench_default.toml" --seed 7 -o "$work/by_path.csv" 2> /dev/null
cmp -s "$work/by_name.csv" "$work/by_path.csv" || fail "bench_default is not the shipped scenario"

echo "simulate_cli: ok"

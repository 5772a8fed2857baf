#!/usr/bin/env bash
# End to end through the binary: `accelcal record` from each kind of source that needs no
# hardware (file, standard input, sim), the recording fitted, and a bad spec.
# Called by ctest as: record_cli.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
source "$(dirname "$0")/lib/common.bash"

# A recording replayed from a file, then fitted: the imu_tk tool's 38 intervals.
expect 0 "$accelcal" record --source "file:$data/imu_tk/xsens_acc.mat" -o "$work/imu.txt"
grep -q "end of input; 51175 samples written" "$work/err" || { cat "$work/err"; fail "file record"; }
grep -q "ended, 100.0 Hz, 51175 samples, 0 malformed, 0 gaps" "$work/err" || fail "file status"
expect 0 "$accelcal" fit --recording "$work/imu.txt" --gravity 9.81744
grep -q "static intervals: 38 found" "$work/out" || fail "imu_tk intervals after record"

# Standard input from a pipe, with a malformed line reported but not fatal.
{ echo "# from a pipe"; for i in $(seq 0 199); do echo "$i.5 $i 2000 3000"; done; echo "300 x 1 2"; } \
  | "$accelcal" record --source - -o "$work/pipe.txt" 2>"$work/err" || fail "record from stdin"
[ "$(grep -vc '^#' "$work/pipe.txt")" -eq 200 ] || fail "stdin sample count"
grep -q "1 malformed line skipped; latest: line 202, column 5: field 'ax': 'x' is not a number" \
  "$work/err" || { cat "$work/err"; fail "malformed line report"; }

# The simulated bench, as fast as possible: 30 s of samples at 100 Hz.
expect 0 "$accelcal" record --source sim --speed 0 --duration 30 -o "$work/sim.txt"
[ "$(grep -vc '^#' "$work/sim.txt")" -eq 3000 ] || fail "sim sample count"
grep -q "duration reached; 3000 samples written" "$work/err" || fail "sim stop reason"

# Ctrl-C: what was received is written, exit status 0.
"$accelcal" record --source sim --speed 20 -o "$work/int.txt" 2>"$work/err" &
pid=$!
for _ in $(seq 1 100); do grep -q "samples" "$work/err" 2>/dev/null && break; sleep 0.1; done
kill -INT "$pid"
wait "$pid" || fail "record after SIGINT exited $?"
grep -q "interrupted" "$work/err" || { cat "$work/err"; fail "interrupt not reported"; }
[ "$(grep -vc '^#' "$work/int.txt")" -gt 0 ] || fail "nothing written after SIGINT"

# A bad spec: exit 1, one line on stderr.
expect 1 "$accelcal" record --source foo -o "$work/x.txt"
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "more than one line on stderr"
grep -q "accelcal: error: unknown source 'foo': expected sim, file:PATH, serial:DEVICE@BAUD, tcp:HOST:PORT, mavlink:LINK, iio:NAME or -" \
  "$work/err" || { cat "$work/err"; fail "bad spec message"; }
expect 1 "$accelcal" record --source serial:/dev/ttyUSB0@12345 -o "$work/x.txt"
grep -q "unsupported baud rate 12345; supported: 300, 1200" "$work/err" || fail "baud message"
expect 2 "$accelcal" record --source sim

expect 0 "$accelcal" record --help
grep -q "Example" "$work/out" || fail "record --help has no example"
echo "record_cli: all checks passed"

#!/usr/bin/env bash
# Issue 30, IIO: the fake device tree fed from the virtual bench (tests/peers/fake_iio.py), and
# the faults: a scan type the reader does not understand, a _raw file that reads -EIO, a device
# that goes away mid-capture, a buffer overrun; the older buffer/ + scan_elements/ layout, an
# ADC's voltage channels with another one left off, big-endian and shifted types, polling at the
# rate asked with the rate reached said. Then libiio's own tools (Debian libiio-utils: iio_info,
# iio_attr) read the same tree mounted at /sys/bus/iio/devices in a private mount namespace
# (`unshare -m`), and accelcal reads it there by its default path: both say the same channels,
# scan types, scale and sampling frequency.
# Usage: bash iio_devices.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
. "$source_dir/tests/e2e/lib/remote_bench.bash"
trap 'stop_bench; rm -rf "$work"' EXIT
fake=$source_dir/tests/peers/fake_iio.py
err_says() { flat "$work/err" "$1" || { cat "$work/err" >&2; fail "not said: $1"; }; }

# iio_record DURATION FAKE_ARGS... -- SOURCE_OPTIONS: the bench at speed 10 behind a fake device
# in $work/iio, `accelcal record` from it; stderr in $work/err.
iio_record() {
  local duration=$1; shift
  local args=() options=""
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do args+=("$1"); shift; done
  [ $# -gt 0 ] && { shift; options=${1:-}; }
  rm -rf "$work/iio" && mkdir -p "$work/iio"
  start_bench 10 python3 "$fake" "$work/iio" "${args[@]}"
  set +e
  timeout 120 "$accelcal" record --source "iio:adxl345,root=$work/iio,dev=$work/iio/iio:device0.fifo$options" \
    --duration "$duration" -o "$work/rec.txt" > /dev/null 2> "$work/err"
  record_status=$?
  set -e
  stop_bench
}

# Buffered, the 5.11 layout, le:s12/16>>4: samples at the rate asked, scale stated not applied.
iio_record 4 --type 'le:s12/16>>4' --bias 2048 -- ",rate=100"
[ "$record_status" -eq 0 ] || { cat "$work/err"; fail "buffered record"; }
err_says "iio:device0 (adxl345): buffered in_accel_x, in_accel_y, in_accel_z as raw counts (in_accel_scale 0.038307 and no offset stated, not applied)"
err_says "records of 16 bytes from $work/iio/iio:device0.fifo (le:s12/16>>4, timestamp channel); trigger: adxl345-dev0"
err_says "sampling_frequency asked 100 Hz, read back 100 Hz"
err_says "up, 100.0 Hz"
awk '!/^#/ && ($4 < 200 || $4 > 500) { exit 1 }' "$work/rec.txt" || fail "z is not the bench's z - 2048 counts"

# The older layout, big-endian unsigned, an ADC's voltage channels with a fourth one left off.
iio_record 4 --layout buffer --type 'be:u12/16>>0' --channels voltage0,voltage1,voltage2 --extra voltage3 \
  --scale 0.4395 -- ",x=voltage0,y=voltage1,z=voltage2"
[ "$record_status" -eq 0 ] || { cat "$work/err"; fail "legacy layout record"; }
err_says "in_voltage0, in_voltage1, in_voltage2 as raw counts (in_voltage_scale 0.4395"
err_says "be:u12/16>>0"
awk '!/^#/ && ($2 < 1800 || $2 > 2300) { exit 1 }' "$work/rec.txt" || fail "voltage0 is not the bench's x counts"

# A buffer overrun: every 50th record missing; the samples lost are named with their t.
iio_record 6 --skip-every 50
err_says "sample lost between t ="
err_says "(buffer overrun: the records were not read fast enough, or the device skipped them)"

# A scan type the reader does not understand: refused, named.
iio_record 2 --type 'le:s12/12>>4'
[ "$record_status" -eq 1 ] || fail "a type not understood was accepted"
err_says "iio:device0 (adxl345): in_accel_x_type: scan type 'le:s12/12>>4' not understood: storage of 12 bits"

# Polling without a buffer: the rate reached said; a _raw reading -EIO; the device going away.
iio_record 3 --layout none -- ",rate=50"
err_says "polled in_accel_x, in_accel_y, in_accel_z"
err_says "polling in_*_raw at 50 Hz"
grep -Eq "polling in_\*_raw at 50 Hz, (4[5-9]|5[0-2])\.[0-9] Hz reached" "$work/err" || { cat "$work/err"; fail "poll rate reached"; }
rm -rf "$work/iio" && mkdir -p "$work/iio"
start_bench 10 python3 "$fake" "$work/iio" --layout none --eio-after 1.5 --vanish-after 4
set +e
timeout 60 "$accelcal" record --source "iio:adxl345,root=$work/iio" --duration 60 -o "$work/rec.txt" > /dev/null 2> "$work/err" &
rec=$!
for _ in $(seq 150); do grep -q "the device went away" "$work/err" 2>/dev/null && break; sleep 0.1; done
kill -INT "$rec"; wait "$rec"
set -e
stop_bench
err_says "iio:adxl345,root=$work/iio iio:device0 (adxl345): in_accel_y_raw: read: Input/output error"
err_says "accelcal record: link lost: iio:adxl345,root=$work/iio iio:device0 (adxl345): the device went away ($work/iio/iio:device0 is gone)"

# The device going away in the middle of the wizard: no sample comes, the capture (the noise
# floor's quiet period) gives up on the wall clock and says why, nothing is stored from after.
short_procedure
sed -i -e 's/^capture_timeout_s = 60 /capture_timeout_s = 4 /' "$work/short.toml"
rm -rf "$work/iio" && mkdir -p "$work/iio"
start_bench 10 python3 "$fake" "$work/iio" --type 'le:u12/16>>0' --vanish-after 1
sleep 1.5
set +e
{ printf 'BENCH-7\ntester\n'; for _ in $(seq 6); do echo; done; } | timeout 120 "$accelcal" wizard \
  --source "iio:adxl345,root=$work/iio,dev=$work/iio/iio:device0.fifo" --bench-control "127.0.0.1:$bench_port" \
  --procedure "$work/short.toml" --session "$work/gone.db" --plain > "$work/out" 2> "$work/err"
code=$?
set -e
stop_bench
[ "$code" -eq 1 ] || { tail "$work/out" "$work/err"; fail "a device gone before the wizard: exit $code"; }
flat "$work/err" "iio:adxl345: no such device in $work/iio; it has no IIO device" || { cat "$work/err"; fail "gone: not said"; }
[ ! -e "$work/gone.db" ] || fail "a session was created for a device that is not there"

# libiio's tools on the same tree, mounted where they look, in a private mount namespace.
if ! command -v iio_info >/dev/null || ! command -v iio_attr >/dev/null; then
  echo "iio_devices: ok (libiio's tools not installed: the cross-check was not run)"; exit 0
fi
rm -rf "$work/iio" && mkdir -p "$work/iio"
# buffer/ + scan_elements/: Debian 12's libiio (0.24) reads the scan elements there only.
python3 "$fake" "$work/iio" --layout buffer --type 'le:s12/16>>4' --extra temp < /dev/null > /dev/null
cat > "$work/ns.sh" <<EOF
set -e
mount -t tmpfs accelcal-test /sys/bus
mkdir -p /sys/bus/iio/devices
mount --bind "$work/iio" /sys/bus/iio/devices
iio_info > "$work/iio_info.txt" 2>&1
iio_attr -c adxl345 accel_x scale > "$work/iio_scale.txt" 2>&1
iio_attr -d adxl345 sampling_frequency > "$work/iio_rate.txt" 2>&1
"$accelcal" device-info --source iio:adxl345,poll --listen 0.5 > "$work/ours.txt" 2>&1
EOF
if ! unshare -m bash "$work/ns.sh" 2> "$work/ns.err"; then
  echo "iio_devices: ok; libiio cross-check not run: a private mount namespace is not allowed here ($(head -1 "$work/ns.err"))"
  exit 0
fi
# (libiio writes the sign in capitals when the value fills its storage: le:S64/64.)
for text in "iio:device0: adxl345 (buffer capable)" "accel_x: (input, index: 0, format: le:s12/16>>4)" \
            "accel_z: (input, index: 2, format: le:s12/16>>4)" "timestamp: (input, index: 4, format: le:S64/64>>0)"; do
  flat "$work/iio_info.txt" "$text" || { cat "$work/iio_info.txt"; fail "iio_info: $text"; }
done
grep -q "^0.038307$" "$work/iio_scale.txt" || { cat "$work/iio_scale.txt"; fail "iio_attr scale"; }
grep -q "^100$" "$work/iio_rate.txt" || { cat "$work/iio_rate.txt"; fail "iio_attr sampling_frequency"; }
for text in "device: iio:device0 (adxl345) at /sys/bus/iio/devices/iio:device0" \
            "x: in_accel_x, scan element accel_x (le:s12/16>>4, index 0), scale 0.038307 per count (in_accel_scale)" \
            "z: in_accel_z, scan element accel_z (le:s12/16>>4, index 2)" "timestamp: le:s64/64>>0 (index 4), ns" \
            "sampling_frequency: 100 Hz" "trigger: adxl345-dev0"; do
  flat "$work/ours.txt" "$text" || { cat "$work/ours.txt"; fail "device-info: $text"; }
done
echo "iio_devices: ok (libiio's iio_info and iio_attr agree)"

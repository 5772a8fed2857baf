#!/usr/bin/env bash
# Line mode on a live TCP bench never judges samples taken before the answer (issue 27, item 6).
# Once, line mode did not read the link while a question waited: the samples piled up, and the
# next capture judged them ("this pose was already captured as capture 1 (+z up)" after the
# prism was turned to -z up). Here a python3 sample server plays a still sensor in real time
# (lib/pose_server.py, its own generator); the technician (lib/answer_when_asked.py) captures
# +z up, then, at the -z up question, waits 6 s with the sensor still +z up, turns it, waits
# 1.5 s and presses Enter. The capture must be -z up, accepted at once, without a refusal.
# Usage: bash line_mode_live_tcp.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"

cat > "$work/two_poses.toml" <<'EOF'
title = "Two poses on a live bench"
[sensor]
range_g = 6
nominal_scale_counts_per_mps2 = 34.8
nominal_bias_counts = 2048
adc_bits = 12
[checks]
capture_duration_s = 2
capture_timeout_s = 30
expected_noise_counts = 1.5
[[step]]
id = "pose_pz"
kind = "static"
up = [0, 0, 1]
pose = "+z up"
[[step]]
id = "pose_mz"
kind = "static"
up = [0, 0, -1]
pose = "-z up"
EOF

echo "+z" > "$work/pose"
python3 "$source_dir/tests/e2e/lib/pose_server.py" "$work/pose" > "$work/port" &
server=$!
trap 'kill $server 2>/dev/null || true; rm -rf "$work"' EXIT
for _ in $(seq 50); do [ -s "$work/port" ] && break; sleep 0.1; done
port=$(head -1 "$work/port")
[ -n "$port" ] || fail "the sample server did not start"

cat > "$work/technician" <<EOF
ask Device serial number
send SN-LIVE
ask Operator
send me
ask Place
send
ask Local gravity
send
ask press Enter to measure it
send
ask with +z up
send
ask with -z up
sleep 6
write $work/pose -z
sleep 1.5
send
ask Procedure complete
EOF
set +e
timeout 120 python3 "$source_dir/tests/e2e/lib/answer_when_asked.py" "$work/technician" "$work/out" -- \
  "$accelcal" wizard --source "tcp:127.0.0.1:$port" --procedure "$work/two_poses.toml" \
  --session "$work/s.db" --plain
code=$?
set -e
[ "$code" -eq 0 ] || { tail -30 "$work/out" >&2; fail "the session did not end as asked (status $code)"; }
if grep -q "already captured\|problem:\|not accepted" "$work/out"; then
  grep -n "already captured\|problem:\|not accepted" "$work/out" >&2
  fail "a capture judged samples taken before its answer"
fi
# The second capture is -z up: its z reads below the zero-g level (2048 - 341 counts).
"$accelcal" export "$work/s.db" -o "$work/caps.csv" > /dev/null
python3 - "$work/caps.csv" <<'EOF' || fail "the -z up capture does not hold -z up samples"
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
z = {}
for r in rows:
    z.setdefault(r["capture"], []).append(float(r["az"]))
means = [sum(v) / len(v) for _, v in sorted(z.items(), key=lambda kv: int(kv[0]))]
assert len(means) == 2 and means[0] > 2300 and means[1] < 1800, means
EOF
echo "line_mode_live_tcp: ok"

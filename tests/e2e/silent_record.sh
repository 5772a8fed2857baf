#!/usr/bin/env bash
# A record step (the drift and noise records) on a link that falls silent (issue 17, item 6, for
# records): samples come, then the link stays connected and sends nothing readable. The record
# must stop on the wall clock after its silence limit (its step's timeout_s - duration_s: 3 s
# here), say why, keep what it recorded, and the wizard leave at the end of its answers. A
# python3 TCP server plays the link; the outer `timeout 60` only turns a hang into a failure.
# Usage: bash silent_record.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"

sed -e 's/^duration_s = 60 .*/duration_s = 60\ntimeout_s = 63/' \
  "$source_dir/procedures/noise.toml" > "$work/noise.toml"
grep -q '^timeout_s = 63' "$work/noise.toml" || fail "procedure: no timeout_s"

cat > "$work/server.py" <<'PY'
import random, socket, sys, time
mode, seconds = sys.argv[1], float(sys.argv[2])
s = socket.socket()
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.bind(("127.0.0.1", 0))
s.listen(4)
print(s.getsockname()[1], flush=True)
s.settimeout(60)
held = []
rng = random.Random(1)
try:
    while True:
        c, _ = s.accept()
        held.append(c)
        try:
            start = time.monotonic()
            k = 0
            while time.monotonic() - start < seconds:  # a still sensor, z up, at 100 Hz
                lines = []
                for _ in range(10):
                    lines.append("%.2f %d %d %d\n" % (k / 100.0, round(2048 + rng.gauss(0, 1.5)),
                                 round(2048 + rng.gauss(0, 1.5)), round(2389 + rng.gauss(0, 1.7))))
                    k += 1
                c.sendall("".join(lines).encode())
                time.sleep(0.1)
            while mode == "nan":  # then lines that are not samples, for as long as it listens
                c.sendall(b"nan nan nan nan\n")
                time.sleep(0.01)
        except OSError:
            pass
except socket.timeout:
    pass
PY

for mode in silent nan; do
  python3 "$work/server.py" "$mode" 6 > "$work/port" &
  server=$!
  for _ in $(seq 50); do [ -s "$work/port" ] && break; sleep 0.1; done
  port=$(head -1 "$work/port")
  [ -n "$port" ] || fail "$mode: the test server did not start"
  # Serial, operator, place, gravity, Enter for the noise floor, Enter to start the record; end.
  set +e
  printf 'SN1\nme\n\n\n\n\n' | timeout 60 "$accelcal" wizard --source "tcp:127.0.0.1:$port" \
    --procedure "$work/noise.toml" --session "$work/$mode.db" --plain > "$work/out" 2> "$work/err"
  code=$?
  set -e
  kill "$server" 2>/dev/null || true
  wait "$server" 2>/dev/null || true
  rm -f "$work/port"
  [ "$code" -ne 124 ] || { tail -8 "$work/out" >&2; fail "$mode: the wizard hung on a silent link"; }
  [ "$code" -eq 0 ] || { cat "$work/err" >&2; fail "$mode: the wizard exited $code"; }
  grep -q "problem: no samples for [0-9]* s: the record stopped at .* of 1 min 0 s\? *(kept up to its last sample)" "$work/out" \
    || grep -q "problem: no samples for [0-9]* s: the record stopped" "$work/out" \
    || { tail -12 "$work/out" >&2; fail "$mode: no reason given"; }
  grep -q "hint: check the cable or the sample server; Enter goes on with the record" "$work/out" \
    || { tail -12 "$work/out" >&2; fail "$mode: no hint"; }
  grep -q "^Saved. Everything accepted is in session" "$work/out" || fail "$mode: not saved and left"
  # The record is kept: `allan` reads it back (a few seconds of samples, none NaN).
  expect 0 "$accelcal" allan "$work/$mode.db"
  grep -Eq "samples|read" "$work/out" || { cat "$work/out" >&2; fail "$mode: allan of the kept record"; }
done
echo "silent_record: ok"

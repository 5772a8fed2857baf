#!/usr/bin/env bash
# A link that stays connected but sends nothing, or only unreadable lines (issue 17, item 6):
# the line-mode wizard must not hang. A python3 TCP server plays the silent link; the procedure's
# capture timeout is 3 s, and the wizard must give up on the wall clock, say why, and leave at
# the end of its answers. The outer `timeout 60` only turns a hang into a failure (generous: a
# loaded CI machine).
# Usage: bash silent_link.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"

sed -e 's/^capture_timeout_s = 60 /capture_timeout_s = 3 /' \
  "$source_dir/procedures/seed_calibration.toml" > "$work/short.toml"
grep -q '^capture_timeout_s = 3 ' "$work/short.toml" || fail "short procedure: no capture_timeout_s"

cat > "$work/server.py" <<'PY'
import socket, sys, time
mode = sys.argv[1]
s = socket.socket()
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.bind(("127.0.0.1", 0))
s.listen(4)
print(s.getsockname()[1], flush=True)
s.settimeout(60)
held = []
try:
    while True:
        c, _ = s.accept()
        held.append(c)
        if mode == "nan":  # lines that are not samples, for as long as the client listens
            try:
                while True:
                    c.sendall(b"nan nan nan nan\n")
                    time.sleep(0.01)
            except OSError:
                pass
except socket.timeout:
    pass
PY

for mode in silent nan; do
  python3 "$work/server.py" "$mode" > "$work/port" &
  server=$!
  for _ in $(seq 50); do [ -s "$work/port" ] && break; sleep 0.1; done
  port=$(head -1 "$work/port")
  [ -n "$port" ] || fail "$mode: the test server did not start"
  # Serial, operator, place, gravity, equipment, then Enter to measure the noise floor; then
  # end of input.
  set +e
  printf 'SN1\nme\n\n\n\n\n' | timeout 60 "$accelcal" wizard --source "tcp:127.0.0.1:$port" \
    --procedure "$work/short.toml" --session "$work/$mode.db" --plain > "$work/out" 2> "$work/err"
  code=$?
  set -e
  kill "$server" 2>/dev/null || true
  wait "$server" 2>/dev/null || true
  rm -f "$work/port"
  [ "$code" -ne 124 ] || { tail -5 "$work/out" >&2; fail "$mode: the wizard hung on a silent link"; }
  [ "$code" -eq 0 ] || { cat "$work/err" >&2; fail "$mode: the wizard exited $code"; }
  grep -q "problem: no samples for [0-9]* s: the noise floor cannot be measured" "$work/out" \
    || { tail -8 "$work/out" >&2; fail "$mode: no reason given"; }
  grep -q "hint: check the cable or the sample server; Enter measures again, q leaves" "$work/out" \
    || fail "$mode: no hint"
  grep -q "^Saved. Everything accepted is in session" "$work/out" || fail "$mode: not saved and left"
done
echo "silent_link: ok"

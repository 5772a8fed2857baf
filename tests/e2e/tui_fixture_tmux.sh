#!/usr/bin/env bash
# A fixture in the full-screen wizard (issue 31), driven through tmux on 100x30:
# 1. 32 boards (--sensors 32): the capture screen shows every board's stillness and orientation
#    (a head line and a grid: all 32 serials on screen at once), d shows each one's figures.
# 2. The plate of 8 with faults (tests/data/fixture/plate_8_faults.toml: board 2 loose, board 5
#    dead): after a pose, the board left out is named with why and asked about, Enter taking the
#    recommended answer (the dead one: leave out); the wizard goes on to its next pose.
# Usage: bash tui_fixture_tmux.sh ACCELCAL SOURCE_DIR DATA_DIR
set -u
ACCELCAL=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SOURCE_DIR=$2
DATA_DIR=$3

fail() { echo "FAIL: $*"; [ -n "${last_screen:-}" ] && printf '%s\n' "--- screen:" "$last_screen"; exit 1; }
command -v tmux >/dev/null || { echo "SKIP: tmux not installed"; exit 77; }

work=$(mktemp -d)
sock="accelcal_tuifix_$$"
tmx() { tmux -L "$sock" "$@"; }
trap 'tmx kill-server 2>/dev/null; rm -rf "$work"' EXIT

start() {  # NAME WIZARD ARGS...
  local name=$1; shift
  cat > "$work/$name.sh" <<EOS
cd "$work"
"$ACCELCAL" wizard --source sim --speed 0 --session "$work/$name.db" $*
echo "EXIT=\$?" > "$work/$name.exit"
sleep 60
EOS
  tmx new-session -d -s "$name" -x 100 -y 30 "bash '$work/$name.sh'"
}
screen_of() { last_screen=$(tmx capture-pane -p -t "$1" 2>/dev/null); printf '%s' "$last_screen"; }
look() { last_screen=$(tmx capture-pane -p -t "$1" 2>/dev/null); s=$last_screen; }  # sets s here
wait_for() {  # NAME SECONDS GREP-PATTERN: Enter to every screen that waits for it, until the pattern shows
  local name=$1 until=$((SECONDS + $2)) pattern=$3 s
  while [ $SECONDS -lt "$until" ]; do
    sleep 0.3
    [ -s "$work/$name.exit" ] && fail "$name: the wizard left: $(cat "$work/$name.exit")"
    s=$(screen_of "$name")
    echo "$s" | grep -q -- "$pattern" && return 0
    echo "$s" | grep -q '  Enter [a-z]' && tmx send-keys -t "$name" Enter 2>/dev/null
  done
  fail "$name: never saw '$pattern'"
}

# --- 1. 32 boards: every one on the capture screen.
start many --sensors 32
wait_for many 120 'sensors  [0-9]* of 32 still and in their pose'
look many
for n in $(seq -w 1 32); do
  echo "$s" | grep -q "SIM$n " || fail "many: SIM$n not on the screen"
done
[ "$(echo "$s" | awk '{ if (length($0) > 100) n++ } END { print n + 0 }')" = 0 ] || fail "many: a line wider than 100"
echo "$s" | grep -q 'd figures' || fail "many: the keys line does not offer d"
# d: each board's figures (its noise against the plate's, its angle from the pose asked).
tmx send-keys -t many d
sleep 0.8
look many
echo "$s" | grep -q 'SIM[0-9]* *[a-z +-]*: std x [0-9.]* y [0-9.]* z [0-9.]* counts' || fail "many: no figures after d"
echo "many: 32 boards on screen, figures on d"
tmx send-keys -t many q
for _ in $(seq 50); do [ -s "$work/many.exit" ] && break; sleep 0.1; done
grep -q 'EXIT=0' "$work/many.exit" || fail "many: q did not leave cleanly"

# --- 2. The faulty plate: a board left out is asked about; Enter takes the recommended answer.
start faults --scenario "$DATA_DIR/fixture/plate_8_faults.toml"
wait_for faults 180 'sensor 5 (B05) left out of'
look faults
echo "$s" | tr -s ' \n' ' ' | grep -q 'sensor 5 (B05) left out of .*no samples' || fail "faults: B05 named without why"
echo "$s" | grep -q 'Enter leave out' || fail "faults: leave out is not what Enter does for the dead board"
echo "$s" | grep -q 'B05 ! link dead' || fail "faults: the grid does not show B05's dead link"
tmx send-keys -t faults Enter
sleep 1
look faults
echo "$s" | grep -q 'Enter leave out' && fail "faults: still asked about B05 after Enter"
echo "$s" | grep -q '^\[DONE\]' || fail "faults: no confirmation after Enter"
echo "$s" | tr -s ' \n' ' ' | grep -q 'sensor 5 (B05) left out of' || fail "faults: leaving B05 out not said"
echo "faults: the dead board named, left out on Enter"
tmx send-keys -t faults q
for _ in $(seq 50); do [ -s "$work/faults.exit" ] && break; sleep 0.1; done
grep -q 'EXIT=0' "$work/faults.exit" || fail "faults: q did not leave cleanly"
echo "PASS"

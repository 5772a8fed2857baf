#!/usr/bin/env bash
# The ncurses wizard driven through tmux (send-keys, capture-pane): a full session on the
# simulator to the report, a resize in the middle, then a second session in NO_COLOR that is
# left with q. Checks what is on screen, the exit status and that the terminal is restored.
# Usage: bash tui_tmux.sh ACCELCAL SOURCE_DIR DATA_DIR
set -u
ACCELCAL=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")  # the wizard runs in a scratch dir
SOURCE_DIR=$2

fail() { echo "FAIL: $*"; [ -n "${last_screen:-}" ] && printf '%s\n' "--- screen:" "$last_screen"; exit 1; }

# 77: CTest's skip code (SKIP_RETURN_CODE in tests/CMakeLists.txt): shown as skipped, never as
# passed. scripts/setup.sh installs tmux, so CI runs this test.
command -v tmux >/dev/null || { echo "SKIP: tmux not installed"; exit 77; }
# An unknown subcommand's --help prints the main help (status 0), so look at the usage line: a
# binary without a working wizard fails here.
"$ACCELCAL" wizard --help 2>/dev/null | grep -q '^Usage: .*wizard' || fail "accelcal wizard --help has no wizard usage line"

work=$(mktemp -d)
sock="accelcal_tui_$$"  # a private tmux server: nothing of the user's is touched
tmx() { tmux -L "$sock" "$@"; }
trap 'tmx kill-server 2>/dev/null; rm -rf "$work"' EXIT

# Starts the wizard in a detached session of the given size. After it exits, the pane's shell
# writes its exit status and the terminal modes (icanon and echo must be back on).
start() {  # NAME COLS ROWS [VAR=VALUE] [WIZARD ARGS...]
  local name=$1 cols=$2 rows=$3 vars=${4:-}; shift 3; [ $# -gt 0 ] && shift
  cat > "$work/$name.sh" <<EOS
cd "$work"
env $vars "$ACCELCAL" wizard --source sim --speed 0 --session "$work/$name.db" $*
status=\$?
echo "EXIT=\$status \$(stty -a | grep -o -- ' -\\?icanon') \$(stty -a | grep -o -- ' -\\?echo ')" > "$work/$name.exit"
sleep 60
EOS
  tmx new-session -d -s "$name" -x "$cols" -y "$rows" "bash '$work/$name.sh'"
}

screen_of() { last_screen=$(tmx capture-pane -p -t "$1" 2>/dev/null); printf '%s' "$last_screen"; }

wait_exit() {  # NAME: waits for the exit file, prints its line
  local i
  for i in $(seq 1 100); do
    [ -s "$work/$1.exit" ] && { cat "$work/$1.exit"; return 0; }
    sleep 0.1
  done
  fail "$1: the wizard did not exit"
}

check_restored() {  # NAME
  local line; line=$(wait_exit "$1")
  echo "$1: $line"
  case "$line" in EXIT=0*) ;; *) fail "$1: exit status not 0: $line" ;; esac
  echo "$line" | grep -q -- ' icanon' || fail "$1: terminal left without icanon: $line"
  echo "$line" | grep -q -- ' echo' || fail "$1: terminal left without echo: $line"
}

# --- 1. A full session, with a resize on the way.
start full 100 32
deadline=$((SECONDS + 120))
seen_step=0 seen_prism=0 seen_keys=0 resized=0 done=0
while [ $SECONDS -lt $deadline ]; do
  sleep 0.5
  [ -s "$work/full.exit" ] && fail "the wizard left before its final screen: $(cat "$work/full.exit")"
  s=$(screen_of full)
  echo "$s" | head -1 | grep -q 'Step [0-9]* of [0-9]*' && seen_step=1
  echo "$s" | grep -q -- '+--------+\|o---->' && seen_prism=1
  echo "$s" | grep -q 'q save and quit\|any key leave' && seen_keys=1
  if [ $seen_prism = 1 ] && [ $resized = 0 ]; then
    tmx resize-window -t full -x 70 -y 24
    sleep 0.5
    s=$(screen_of full)
    echo "$s" | head -1 | grep -q 'Step' || fail "after the resize the header is gone"
    [ "$(echo "$s" | awk '{ if (length($0) > 70) n++ } END { print n + 0 }')" = 0 ] ||
      fail "after the resize a line is wider than 70"
    echo "$s" | grep -q 'q save and quit' || fail "after the resize the keys are gone"
    resized=1
  fi
  if echo "$s" | grep -q 'any key leave'; then done=1; break; fi
  tmx send-keys -t full Enter 2>/dev/null
done
[ $seen_step = 1 ] || fail "never saw 'Step k of n' in the header"
[ $seen_prism = 1 ] || fail "never saw the prism drawing"
[ $seen_keys = 1 ] || fail "never saw the keys line"
[ $resized = 1 ] || fail "no resize was tried"
[ $done = 1 ] || fail "the session did not reach its final screen in 120 s"
echo "full: final screen reached"
tmx send-keys -t full q
check_restored full

# --- 2. The clumsy bench in the TUI: a procedure of one step, a scenario with one fault; Enter
# until the final screen; what the technician is told must have been on the screen.
# Enter is sent only to a screen that waits for it (its keys line offers Enter), never while a
# measurement runs: a key sent during a capture could otherwise be read by the refusal that
# ends it, and the refusal would leave the screen between two looks (flaky on a loaded machine).
# A screen that waits does not change by itself, so the text is always seen before Enter goes.
# The deadline only guards against a hang.
# Usage: clumsy NAME SCENARIO STEP_ID TEXT
seed_procedure="$SOURCE_DIR/procedures/full_calibration.toml"
clumsy() {
  local name=$1 scenario=$2 step=$3 text=$4
  { sed '/^\[\[step\]\]/,$d' "$seed_procedure"
    awk -v id="$step" 'BEGIN { RS = ""; ORS = "\n\n" }
      $0 ~ "\\[\\[step\\]\\]\nid = \"" id "\"" { sub(/^[^[]*\[\[step\]\]/, "[[step]]"); print }' "$seed_procedure"
  } > "$work/$name.toml"
  start "$name" 100 32 "" --scenario "$SOURCE_DIR/scenarios/$scenario" --procedure "$work/$name.toml"
  local deadline=$((SECONDS + 240)) seen=0
  while [ $SECONDS -lt $deadline ]; do
    sleep 0.3
    s=$(screen_of "$name")
    echo "$s" | tr -s ' \n' ' ' | grep -qF "$text" && seen=1
    echo "$s" | grep -q 'any key leave' && break
    echo "$s" | grep -q '  Enter [a-z]' && tmx send-keys -t "$name" Enter 2>/dev/null
  done
  [ $seen = 1 ] || fail "$name: never saw '$text' on the screen"
  echo "$s" | grep -q 'any key leave' || fail "$name: no final screen"
  tmx send-keys -t "$name" q
  check_restored "$name"
  echo "$name: told '$text'"
}
clumsy axis clumsy_wrong_axis.toml tt_x_050 "wrong mounting: the samples show +y radial, +z up"
clumsy level clumsy_tilted_table.toml level "the table is not level: raise the left side by about"

# --- 3. NO_COLOR: no colour escapes on screen; Ctrl-X saves and leaves in the middle.
start mono 100 32 NO_COLOR=1
sleep 2
tmx send-keys -t mono Enter
sleep 1
esc=$(tmx capture-pane -e -p -t mono)
last_screen=$esc
echo "$esc" | head -1 | grep -q 'Step' || fail "mono: no header"
if printf '%s' "$esc" | grep -q $'\e\\[[0-9;]*[34][0-7]m\|\e\\[[0-9;]*[34]8;'; then
  fail "mono: colour escapes with NO_COLOR=1"
fi
# At a text field (the welcome's second answer) q is a letter: Ctrl-X saves and quits.
tmx send-keys -t mono C-x
check_restored mono
# The session file exists once the SQLite journal is wired in; the in-memory one writes none.
if [ -s "$work/mono.db" ]; then echo "mono: session saved"; else echo "NOTE: no session file written"; fi
echo "PASS"

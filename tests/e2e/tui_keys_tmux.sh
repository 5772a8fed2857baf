#!/usr/bin/env bash
# The TUI's text fields, keys and help through tmux (issue 15): the key bar at a text field
# offers only keys that work there; ? and F1 open the help (at a text field too, never typed);
# letters are typed; after a refused turntable plan the cursor is on the speed and the default is
# not the refused speed; a speed typed at the radius sets the speed; Ctrl-X saves and quits.
# ACCELCAL_SCREENSHOTS=DIR keeps each checked screen (capture-pane -e) there.
# Usage: bash tui_keys_tmux.sh ACCELCAL SOURCE_DIR DATA_DIR
set -u
ACCELCAL=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SOURCE_DIR=$2
fail() { echo "FAIL: $*"; [ -n "${last_screen:-}" ] && printf '%s\n' "--- screen:" "$last_screen"; exit 1; }
command -v tmux >/dev/null || { echo "SKIP: tmux not installed"; exit 77; }

work=$(mktemp -d)
sock="accelcal_keys_$$"
tmx() { tmux -L "$sock" "$@"; }
trap 'tmx kill-server 2>/dev/null; rm -rf "$work"' EXIT

# The seed procedure cut to its first turntable step.
seed="$SOURCE_DIR/procedures/full_calibration.toml"
{ sed '/^\[\[step\]\]/,$d' "$seed"
  awk 'BEGIN { RS = ""; ORS = "\n\n" }
    $0 ~ "\\[\\[step\\]\\]\nid = \"tt_x_050\"" { sub(/^[^[]*\[\[step\]\]/, "[[step]]"); print }' "$seed"
} > "$work/tt.toml"
grep -q 'tt_x_050' "$work/tt.toml" || fail "no turntable step in the procedure"

cat > "$work/run.sh" <<EOS
cd "$work"
"$ACCELCAL" wizard --source sim --speed 0 --session "$work/k.db" --procedure "$work/tt.toml"
echo "EXIT=\$?" > "$work/k.exit"
sleep 60
EOS
tmx new-session -d -s k -x 100 -y 30 "bash '$work/run.sh'"

shot=0
screen() { last_screen=$(tmx capture-pane -p -t k 2>/dev/null); printf '%s' "$last_screen"; }
keep() {  # NAME: the screen with its colours, for a look by eye
  [ -n "${ACCELCAL_SCREENSHOTS:-}" ] || return 0
  shot=$((shot + 1))
  tmx capture-pane -e -p -t k > "$ACCELCAL_SCREENSHOTS/$(printf '%02d' $shot)_$1.ans"
}
# wait_for TEXT: until TEXT is on the screen (blanks squeezed), 20 s at most.
wait_for() {
  local i
  for i in $(seq 1 100); do
    screen | tr -s ' \n' ' ' | grep -qF -- "$1" && return 0
    sleep 0.2
  done
  fail "never saw '$1'"
}
keys_row() { screen | awk 'NF { last = $0 } END { print last }'; }
send() { tmx send-keys -t k "$@"; sleep 0.3; }

# --- The welcome: a text field.
wait_for "Device serial number"
row=$(keys_row)
echo "$row" | grep -q 'Ctrl-X save and quit' || fail "welcome keys: $row"
echo "$row" | grep -q 'Esc back' || fail "welcome keys: $row"
echo "$row" | grep -q '? help' || fail "welcome keys: $row"
echo "$row" | grep -q ' q save\| b back\| s skip' && fail "welcome keys offer letters: $row"
keep welcome
send '?'
wait_for "Help: what this step expects"
wait_for "serial number, from its label"
keep welcome_help
send Enter  # closes the help only
wait_for "Device serial number"
screen | grep -q 'answer \[SIM-0001\]: _' || fail "the key that closed the help did something else"
for i in 1 2 3 4 5; do send Enter; done  # the rest of the welcome (its last: the equipment)

# --- The radius: letters are typed, the bar offers the untypable keys.
wait_for "Radius from the spin axis"
row=$(keys_row)
for k in 'Ctrl-X save and quit' 'Enter accept' 'Esc back' 'Ctrl-N skip' '? help'; do
  echo "$row" | grep -qF "$k" || fail "radius keys lack '$k': $row"
done
echo "$row" | grep -q ' s skip\| b back' && fail "radius keys offer letters: $row"
keep radius
send s b
screen | grep -q 'answer \[50 mm\]: sb_' || fail "s and b were not typed into the answer"
keys_row | grep -q 'Esc clear' || fail "with text typed the bar does not say Esc clears"
send Escape
screen | grep -q 'answer \[50 mm\]: _' || fail "Esc did not clear the answer"
# A speed typed at the radius sets the speed (never "unknown unit 'rpm' for a radius").
send -l '600 rpm'; send Enter
wait_for "Speed set to 600 rpm; now the radius"
keep speed_at_radius
screen | grep -q "unknown unit" && fail "unknown unit at the radius"
send Enter  # the radius's default, 50 mm
wait_for "Table speed"
send Enter  # 600 rpm: refused
wait_for "lower the speed or the radius"
screen | grep -q 'Table speed' || fail "after the refusal the cursor is not on the speed"
screen | grep -q 'answer \[120 rpm\]: _' || fail "the refused speed became the default"
keep refused_plan
tmx send-keys -t k F1; sleep 0.3
wait_for "Type the table's speed"
keep speed_help
send x  # closes the help, not typed
screen | grep -q 'answer \[120 rpm\]: _' || fail "the key that closed the help was typed"
send -l '2 Hz'
send C-x  # saves and quits from a text field
for i in $(seq 1 50); do [ -s "$work/k.exit" ] && break; sleep 0.2; done
[ -s "$work/k.exit" ] || fail "Ctrl-X did not quit"
grep -q 'EXIT=0' "$work/k.exit" || fail "exit status: $(cat "$work/k.exit")"
[ -s "$work/k.db" ] || fail "no session saved"
echo "PASS"

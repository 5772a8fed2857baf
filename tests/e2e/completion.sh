#!/usr/bin/env bash
# The bash completion the build writes (build/share/bash-completion/completions/accelcal), run
# in bash as readline would: COMP_LINE/COMP_POINT/COMP_WORDS set, _accelcal called, COMPREPLY
# read. Commands (every one --help lists), options, the values of --source (with fake serial
# ports), procedures and scenarios (the shipped ones, as the program finds them, and *.toml),
# session files, choices. Usage: completion.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$(realpath "$1")
script=$(dirname "$accelcal")/share/bash-completion/completions/accelcal
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
[ -f "$script" ] || fail "no completion script at $script"

# A directory to complete in, and a fake /dev with two serial ports and a terminal.
mkdir -p "$work/here/sub" "$work/dev"
touch "$work/here/bench.db" "$work/here/old.db" "$work/here/mine.toml" "$work/here/notes.txt" \
      "$work/dev/ttyUSB0" "$work/dev/ttyACM1" "$work/dev/tty0"
cd "$work/here"

# completions_of LINE: the completions of LINE (cursor at its end), one a line, sorted.
completions_of() {
  COMPLETION_LINE=$1 ACCELCAL_COMPLETION_DEV="$work/dev" bash -c '
    . "$0"
    COMP_LINE=$COMPLETION_LINE; COMP_POINT=${#COMP_LINE}
    read -ra COMP_WORDS <<< "$COMP_LINE"
    [[ $COMP_LINE == *" " ]] && COMP_WORDS+=("")
    COMP_CWORD=$(( ${#COMP_WORDS[@]} - 1 ))
    _accelcal
    printf "%s\n" "${COMPREPLY[@]}"' "$script" | sed '/^$/d' | sort
}
# expect_completions LINE WORD...: exactly these completions.
expect_completions() {
  local line=$1; shift
  local got want
  got=$(completions_of "$line")
  want=$(printf '%s\n' "$@" | sed '/^$/d' | sort)
  [ "$got" = "$want" ] || fail "'$line': got [$(echo $got)], expected [$(echo $want)]"
}
# expect_has LINE WORD...: these among the completions.
expect_has() {
  local line=$1; shift
  local got
  got=$(completions_of "$line")
  for w in "$@"; do grep -qxF -- "$w" <<< "$got" || fail "'$line': no '$w' in [$(echo $got)]"; done
}

# Every command --help lists, and nothing hidden.
commands=$("$accelcal" --help | awk '/^Subcommands:/{on=1; next} on && !/^ /{exit} on && /^  [a-z]/{print $1}' | sort)
[ "$(echo "$commands" | wc -l)" -ge 12 ] || fail "too few commands in --help: $commands"
[ "$(completions_of "$accelcal ")" = "$commands" ] || fail "commands: got [$(completions_of "$accelcal " | xargs)]"
expect_completions "$accelcal wi" wizard
expect_completions "$accelcal --v" --version
expect_completions "$accelcal help-" ""

# Options, after a flag too (a flag takes no value).
expect_completions "$accelcal wizard --so" --source
expect_completions "$accelcal wizard --plain --ses" --session
expect_has "$accelcal fit --" --recording --output --no-diagnose --gravity --help

# Sources: the forms, the serial ports present, bauds; file: completes files. ':' and '=' break
# words in bash, so each completion is what follows the last of them.
expect_completions "$accelcal wizard --source " sim - file: serial: tcp: mavlink: iio: \
  "serial:$work/dev/ttyUSB0@" "serial:$work/dev/ttyACM1@"
expect_completions "$accelcal wizard --source serial:" "$work/dev/ttyUSB0@" "$work/dev/ttyACM1@"
expect_has "$accelcal record --source serial:$work/dev/ttyUSB0@" "$work/dev/ttyUSB0@115200" "$work/dev/ttyUSB0@9600"
expect_completions "$accelcal wizard --source=s" sim serial: "serial:$work/dev/ttyUSB0@" "serial:$work/dev/ttyACM1@"
expect_completions "$accelcal record --source file:no" notes.txt
expect_completions "$accelcal record --source tcp:" ""

# Procedures and scenarios: the shipped ones (as the program finds them), *.toml files, folders.
shipped=$(ls "$source_dir/procedures" | grep '\.toml$')
# shellcheck disable=SC2086
expect_completions "$accelcal wizard --procedure " $shipped mine.toml sub
expect_has "$accelcal wizard --scenario clumsy_" clumsy_bump.toml clumsy_wrong_axis.toml
expect_has "$accelcal simulate " bench_default.toml mine.toml
expect_completions "$accelcal export-cal c.json --procedure no" noise.toml

# Sessions: *.db and folders; choices; nothing for a number or a device serial.
expect_completions "$accelcal wizard --session " bench.db old.db sub
expect_completions "$accelcal export " bench.db old.db sub
expect_completions "$accelcal export-cal c.json --to " c-header ardupilot px4 kalibr csv
expect_completions "$accelcal export-cal c.json --to=p" px4
expect_completions "$accelcal wizard --speed " ""
expect_completions "$accelcal history " ""
expect_has "$accelcal fit " bench.db mine.toml notes.txt sub

# Installed the way bash-completion loads it: the script registers itself for the command name.
bash -c '. "$0"; complete -p accelcal' "$script" | grep -q -- "-F _accelcal accelcal" || fail "not registered"
echo ok

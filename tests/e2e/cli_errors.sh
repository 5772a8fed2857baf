#!/usr/bin/env bash
# The command line's errors through the real binary (issue 15): every error is one
# "accelcal: error:" line (a suggestion may follow), exit 1 for bad input or a refusal, 2 for a
# wrong command line; a mistyped option gets "did you mean"; a bound is readable; a serial port
# that is not there is refused before a session file exists; `accelcal sessions` keeps its
# columns with long fields. Usage: cli_errors.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2
make_session=$(dirname "$accelcal")/accelcal_make_session
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"

# expect CODE CMD...: runs CMD, checks its exit status, keeps stdout/stderr in $work/out, err.
expect() {
  local want=$1; shift
  set +e; "$@" >"$work/out" 2>"$work/err" </dev/null; local got=$?; set -e
  [ "$got" -eq "$want" ] || { cat "$work/err" >&2; fail "'$*' exited $got, expected $want"; }
  if [ "$want" -ne 0 ]; then
    head -1 "$work/err" | grep -q '^accelcal: error: ' || { cat "$work/err" >&2; fail "'$*': no 'accelcal: error:' prefix"; }
  fi
}

# A mistyped option: usage (2), with the option it meant.
expect 2 "$accelcal" wizard --sesion x.db
grep -q "^accelcal: error: --sesion: did you mean --session?$" err || { cat err; fail "no suggestion for --sesion"; }
[ ! -e x.db ] || fail "a session file for a refused command line"
: > c.csv  # exists: a missing file named first is refused first (1), before the options are
expect 2 "$accelcal" fit --no-diagnos c.csv
grep -q "did you mean --no-diagnose?" err || { cat err; fail "no suggestion for --no-diagnos"; }
expect 2 "$accelcal" sesions
grep -q "did you mean sessions?" err || { cat err; fail "no suggestion for the subcommand sesions"; }
expect 2 "$accelcal" wizard --frobnicate
grep -q "did you mean" err && fail "a suggestion for a word near nothing: $(cat err)"

# CLI11's own texts never reach the technician (issue 35): each refusal in our words, one line.
: > cal.json
expect_words() {  # expect_words WORDS CMD...: usage (2), stderr's first line exactly WORDS
  local words=$1; shift
  expect 2 "$@"
  [ "$(head -1 "$work/err")" = "accelcal: error: $words" ] || { cat "$work/err"; fail "'$*': not '$words'"; }
  if grep -Eq "At Most|At least|required but|is required|Could not convert|not expected|not in \{|excludes|requires|disallowed|Should be" "$work/err"; then
    cat "$work/err"; fail "'$*': CLI11's raw text"
  fi
}
expect_words "--speed is given twice (20 and 1): give it once" "$accelcal" wizard --speed 20 --speed 1
expect_words "--speed needs a number after it" "$accelcal" wizard --speed
expect_words "--seed: must be a whole number, 0 or more, not -3" "$accelcal" wizard --seed -3
expect_words "--seed: 'x1' is not a whole number, 0 or more" "$accelcal" record --source sim -o r.txt --seed x1
expect_words "accelcal simulate needs its scenario: Scenario file (TOML), or a shipped one's name" "$accelcal" simulate
expect_words "accelcal export-cal needs --to: Target format (one of c-header, ardupilot, px4, kalibr or csv)" \
  "$accelcal" export-cal cal.json
expect_words "--to: 'xml' is not one of c-header, ardupilot, px4, kalibr or csv" "$accelcal" export-cal cal.json --to xml
expect_words "--px4-device-id: 'abc' is not a whole number" "$accelcal" export-cal cal.json --to px4 --px4-device-id abc
expect_words "accelcal wizard does not take 'foo'" "$accelcal" wizard foo
expect_words "accelcal wizard has no option '--frobnicate'" "$accelcal" wizard --frobnicate
expect_words "'bogus' is not a command of accelcal" "$accelcal" bogus
expect_words "--gravity and --latitude cannot be given together" "$accelcal" wizard --gravity 9.8 --latitude 45
expect_words "--altitude needs --latitude too" "$accelcal" wizard --altitude 10
expect_words "--plain is a switch: it takes no value (or true/false)" "$accelcal" wizard --plain=maybe
[ ! -e r.txt ] || fail "a recording for a refused command line"

# A missing input file is bad input (1), whichever command names it, in one line.
expect 1 "$accelcal" fit missing.csv
grep -q "^accelcal: error: no such file: missing.csv$" err || { cat err; fail "fit missing.csv"; }
[ "$(wc -l <err)" -eq 1 ] || fail "fit missing.csv: more than one line"
expect 1 "$accelcal" report missing.db
expect 1 "$accelcal" apply missing.json

# A bound in words, not a 310-digit number.
expect 2 "$accelcal" wizard --speed -1
grep -q "must be 0 or more, not -1" err || { cat err; fail "--speed -1 message"; }
awk 'length($0) > 160 { exit 1 }' err || { cat err; fail "--speed -1: a line longer than 160 characters"; }
expect 2 "$accelcal" record --source sim --duration -5 -o r.txt
grep -q "must be 0 or more, not -5" err || { cat err; fail "--duration -5 message"; }

# A serial port that is not there: refused before any session file is created.
expect 1 "$accelcal" wizard --source serial:/dev/ttyNOPE_accelcal@115200 --session s.db --plain
grep -q "serial port /dev/ttyNOPE_accelcal does not exist" err || { cat err; fail "absent serial port message"; }
[ ! -e s.db ] || fail "a session file was created for an absent serial port"
[ ! -e s.db.lock ] || fail "a lock file was left for an absent serial port"

# sessions: columns stay in place with a long device, a long procedure title and a long name.
mkdir sessions
"$make_session" sessions/short.db
"$make_session" "sessions/a-session-name-far-longer-than-its-column.db" \
  --device "SN-0000000000000000000000000000000042-very-long-serial"
sed '0,/^title = .*/s//title = "A noise record with a title much longer than the procedure column of the listing"/' \
  "$src/procedures/noise.toml" > long_title.toml
grep -q "^title = \"A noise record" long_title.toml || fail "the noise procedure has no title line to change"
"$make_session" sessions/noise.db --noise long_title.toml SN-NOISE 2026-01-02T03:04:05Z 0,0,0 7
expect 0 "$accelcal" sessions sessions
cat out
# Every row's "captures" column ends at the same column as the header's.
python3 - out <<'PY' || fail "sessions: columns moved"
import sys
lines = [l.rstrip("\n") for l in open(sys.argv[1])]
head = lines[0]
end = head.index("captures") + len("captures")
rows = [l for l in lines[1:] if l.strip() and not l.startswith("a-session-name")]
assert len(rows) == 3, rows
for r in rows:
    assert r[end - 1].isdigit() and r[end] == " ", (end, r)
assert any("..." in r for r in rows), rows
PY
grep -q "^a-session-name-far-longer-than-its-column$" out || fail "the long name is cut or not on its own line"
echo ok

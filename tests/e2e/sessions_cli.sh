#!/usr/bin/env bash
# End to end: a session file (made by accelcal_make_session, built beside accelcal) listed by
# `accelcal sessions`, exported and refitted, reported as text and as a calibration file that
# `accelcal apply` reads; and the failure paths. Called by ctest as:
#   sessions_cli.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
make_session=$(dirname "$accelcal")/accelcal_make_session
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
: "$src" "$data"

# expect CODE CMD...: runs CMD, checks its exit status, keeps stdout/stderr in $work/out, err.
expect() {
  local want=$1; shift
  set +e; "$@" >"$work/out" 2>"$work/err"; local got=$?; set -e
  [ "$got" -eq "$want" ] || { cat "$work/err" >&2; fail "'$*' exited $got, expected $want"; }
}

mkdir -p "$work/sessions"
"$make_session" "$work/sessions/bench1.db"
"$make_session" "$work/sessions/half.db" --no-result

# sessions: both listed, with device, operator, procedure, captures, state, calibration.
expect 0 "$accelcal" sessions "$work/sessions"
grep -Eq '^bench1 .* SIM-0001 +e2e +bench_default +18 done +yes$' "$work/out" || { cat "$work/out"; fail "bench1 row"; }
grep -Eq '^half .* 18 open +no$' "$work/out" || { cat "$work/out"; fail "half row"; }

# The default directory comes from XDG_DATA_HOME, and names resolve in it.
mkdir -p "$work/xdg/accelcal/sessions"
cp "$work/sessions/bench1.db" "$work/xdg/accelcal/sessions/"
XDG_DATA_HOME=$work/xdg expect 0 "$accelcal" sessions
grep -q '^bench1 ' "$work/out" || fail "default directory not listed"

# export -> fit: the same parameters as the stored calibration.
XDG_DATA_HOME=$work/xdg expect 0 "$accelcal" export bench1 -o "$work/c.csv"
grep -q "18 captures" "$work/out" || fail "export summary"
grep -q '^capture,kind,t,ax,ay,az,temp_c,radius_m,rpm,label,up_axis$' "$work/c.csv" || fail "csv header"
expect 0 "$accelcal" fit "$work/c.csv" --no-diagnose -o "$work/refit.json"
grep -q "fit converged: 18 captures" "$work/out" || fail "refit"

# report: text, and the calibration file, which apply reads and which matches the refit.
expect 0 "$accelcal" report "$work/sessions/bench1.db"
grep -q "^2. Parameters (1-sigma uncertainties)$" "$work/out" || fail "report parameters"
grep -q "SIM-0001" "$work/out" || fail "report device"
grep -Eq '^ +18 .* turntable ' "$work/out" || fail "report capture table"
expect 0 "$accelcal" report "$work/sessions/bench1.db" --format calibration -o "$work/cal.json"
grep -q '"format": "accelcal-calibration/1"' "$work/cal.json" || fail "calibration format"
printf '0 2051 2040 2400\n' | "$accelcal" apply "$work/cal.json" >"$work/applied" || fail "apply"
# apply reads the session's calibration as report, export-cal and allan do: the same output.
printf '0 2051 2040 2400\n' | "$accelcal" apply "$work/sessions/bench1.db" >"$work/applied_db" || fail "apply session"
cmp -s "$work/applied" "$work/applied_db" || { cat "$work/applied" "$work/applied_db"; fail "apply: session and its calibration file differ"; }
printf '0 2051 2040 2400\n' | XDG_DATA_HOME=$work/xdg "$accelcal" apply bench1 >"$work/applied_name" || fail "apply session by name"
cmp -s "$work/applied" "$work/applied_name" || fail "apply: a session by its name differs"
# A sensor the session does not have: named, nothing written.
set +e
printf '0 2051 2040 2400\n' | "$accelcal" apply "$work/sessions/bench1.db" --sensor 2 >"$work/applied_2" 2>"$work/err_2"
code=$?
set -e
[ "$code" -ne 0 ] && [ ! -s "$work/applied_2" ] || fail "apply --sensor 2 of a one-sensor session: exit $code"
grep -q "sensor" "$work/err_2" || { cat "$work/err_2"; fail "apply --sensor 2: no reason"; }
python3 - "$work/cal.json" "$work/refit.json" <<'PY' || fail "refit differs from the stored calibration"
import json, sys
a, b = ({k: json.load(open(p))[k] for k in ("bias_counts", "scale_counts_per_mps2", "misalignment_rad")} for p in sys.argv[1:3])
def flat(m):
    out = []
    for v in m.values():
        out += flat(v) if isinstance(v, dict) else (v if isinstance(v, list) else [v])
    return out
fa, fb = flat(a), flat(b)
assert len(fa) == len(fb) and all(abs(x - y) <= 1e-6 * max(1.0, abs(x)) for x, y in zip(fa, fb)), (fa, fb)
PY

# A copy with 64 bytes flipped in its middle (issue 17, item 5): the damaged capture is named and
# left out, never shown as data; the report's verdict is INCOMPLETE; export writes the rest.
cp "$work/sessions/bench1.db" "$work/flipped.db"
python3 - "$work/flipped.db" <<'PY'
import os, sys
path = sys.argv[1]
offset = os.path.getsize(path) // 2 // 4096 * 4096 + 1024  # clear of the page header
with open(path, "r+b") as f:
    f.seek(offset); chunk = bytearray(f.read(64))
    f.seek(offset); f.write(bytes(b ^ 0x5A for b in chunk))
PY
expect 0 "$accelcal" report "$work/flipped.db"
grep -q "INCOMPLETE: the capture of step '.*' (.*) is damaged in" "$work/out" \
  || { cat "$work/out"; fail "report does not name the damaged capture"; }
grep -q "INCOMPLETE" "$work/out" || fail "a report with a damaged capture is not INCOMPLETE"
expect 0 "$accelcal" export "$work/flipped.db" -o "$work/flipped.csv"
grep -q "17 captures" "$work/out" || { cat "$work/out"; fail "export of the damaged session"; }
grep -q "^not written: the capture of step '.*' (.*) is damaged in the session file" "$work/err" || { cat "$work/err"; fail "export's reason"; }

# Failure paths: one clear line, exit 1.
expect 1 "$accelcal" report "$work/sessions/half.db"
grep -q "has no calibration yet: 18 captures accepted; run the wizard to finish it" "$work/err" || fail "no-result message"
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "more than one line on stderr"
expect 1 "$accelcal" export "$work/missing.db" -o "$work/x.csv"
grep -q "^accelcal: error: no session $work/missing.db$" "$work/err" || fail "missing session message"
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "more than one line on stderr"
XDG_DATA_HOME=$work/xdg expect 1 "$accelcal" report nosuch
grep -q "no session nosuch" "$work/err" || fail "missing name message"
echo "not a database" >"$work/sessions/junk.db"
expect 1 "$accelcal" report "$work/sessions/junk.db"
grep -q "is not an accelcal session" "$work/err" || fail "foreign file message"
echo ok

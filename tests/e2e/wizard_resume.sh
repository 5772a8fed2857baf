#!/usr/bin/env bash
# kill -9 the wizard at random instants and rerun the same command: it resumes, the accepted
# captures only grow, no step is recorded twice, and the last run finishes with a calibration.
# Called by ctest as: wizard_resume.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
RANDOM=4242  # deterministic kill instants

run_wizard() { { yes '' || true; } | "$accelcal" wizard --source sim --speed 0 --session "$work/s.db" --plain; }

# Every capture's id once per row block; prints "count" of distinct captures exported.
captures_now() {
  [ -f "$work/s.db" ] || { echo 0; return; }
  "$accelcal" export "$work/s.db" -o "$work/c.csv" >/dev/null 2>&1 || { echo 0; return; }
  grep -v '^#' "$work/c.csv" | tail -n +2 | cut -d, -f1 | uniq | tee "$work/ids" | wc -l
}

# Each round is killed when its output has grown past a random size: an instant in the
# session's progress, not in wall-clock time, so a slow (loaded, sanitized) machine kills at the
# same kind of moments as a fast one. A round that finishes before its instant is not killed.
killed_after_bytes() {  # $1: the run's pid, $2: its output file, $3: size in bytes
  local waited=0
  while kill -0 "$1" 2>/dev/null && [ "$(stat -c %s "$2" 2>/dev/null || echo 0)" -lt "$3" ]; do
    sleep 0.005
    waited=$((waited + 1))
    [ "$waited" -lt 12000 ] || fail "a run made no progress in a minute"
  done
  # The wizard runs in a pipeline's subshell; kill -9 the accelcal process itself.
  local target
  target=$(pgrep -P "$1" -x accelcal || true)
  [ -n "$target" ] && kill -9 $target 2>/dev/null || true
}

previous=0 resumed=0
for round in $(seq 1 8); do
  run_wizard >"$work/out.$round" 2>&1 &
  pid=$!
  killed_after_bytes "$pid" "$work/out.$round" $((RANDOM % 9000 + 300))
  wait "$pid" 2>/dev/null || true
  grep -q "Resuming session" "$work/out.$round" && resumed=$((resumed + 1))
  now=$(captures_now)
  [ "$now" -ge "$previous" ] || fail "round $round: captures went from $previous to $now"
  [ "$(sort "$work/ids" 2>/dev/null | uniq -d | wc -l)" -eq 0 ] || fail "round $round: a capture twice"
  previous=$now
done

# The final run completes and the session has its calibration.
run_wizard >"$work/final" 2>&1 || { tail "$work/final" >&2; fail "final run failed"; }
[ "$(captures_now)" -eq 19 ] || fail "expected 19 captures at the end, got $(captures_now)"
[ "$(sort "$work/ids" | uniq -d | wc -l)" -eq 0 ] || fail "a capture twice at the end"
"$accelcal" sessions "$work/s.db" >"$work/list"
grep -Eq ' 19 (open|done) +yes$' "$work/list" || { cat "$work/list"; fail "session not complete"; }
"$accelcal" report "$work/s.db" >"$work/report" || fail "report"
grep -q "^2. Parameters (1-sigma uncertainties)$" "$work/report" || fail "report text"
[ "$previous" -eq 18 ] || [ "$resumed" -gt 0 ] || fail "no round was interrupted mid-session"
echo "ok: $resumed resumed runs"

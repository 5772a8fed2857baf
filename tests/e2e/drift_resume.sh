#!/usr/bin/env bash
# The 12-hour drift record (procedures/drift.toml) on the virtual bench as fast as it goes
# (--speed 0: 12 h of simulated samples at 100 Hz in seconds),
# kill -9 twice in the middle of the record, rerun each time: the record resumes with a gap
# row, no committed chunk is lost or changed (checksums of the chunk rows before and after each
# kill), and the final run completes: span = 12 h, samples = (span - gaps) x 100 Hz.
# Called by ctest as: drift_resume.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
RANDOM=1207  # deterministic delays
db=$work/s.db

# The shipped procedure with chunks of 300 s instead of 10 s: each chunk is an fsynced commit,
# and 4320 of them take a minute or more on a busy CI disk; 144 keep the test to seconds.
sed 's/^chunk_s = 10 /chunk_s = 300 /' "$source_dir/procedures/drift.toml" >"$work/drift.toml"
grep -q '^chunk_s = 300 ' "$work/drift.toml" || fail "procedures/drift.toml has no 'chunk_s = 10' line to change"

run_wizard() {
  { yes '' || true; } | "$accelcal" wizard --procedure "$work/drift.toml" \
    --source sim --speed 0 --session "$db" --plain
}

# One line per committed chunk: index and a checksum of the row (n, times, samples).
chunk_sums() {
  python3 - "$db" <<'PY'
import hashlib, sqlite3, sys
db = sqlite3.connect("file:" + sys.argv[1] + "?mode=ro", uri=True)
try:
    rows = db.execute("SELECT chunk_index, n, t_first_s, t_last_s, samples FROM record_chunks "
                      "WHERE step_id = 'drift' ORDER BY chunk_index").fetchall()
except sqlite3.OperationalError:
    rows = []
for i, n, t0, t1, blob in rows:
    assert len(blob) == 40 * n, f"chunk {i}: {len(blob)} bytes for {n} samples"
    print(i, hashlib.sha1(repr((n, t0, t1)).encode() + blob).hexdigest())
PY
}

chunk_count() {
  python3 - "$db" <<'PY'
import sqlite3, sys
try:
    db = sqlite3.connect("file:" + sys.argv[1] + "?mode=ro", uri=True)
    print(db.execute("SELECT count(*) FROM record_chunks").fetchone()[0])
except sqlite3.Error:
    print(0)
PY
}

# kill -9 the wizard at a random moment once the record holds more than `after` chunks (of
# 144: the run is far from its end, however fast the machine).
run_and_kill() {
  local after=$1 round=$2
  run_wizard >"$work/out.$round" 2>&1 &
  local pid=$! target=""
  for _ in $(seq 1 1200); do
    [ "$(chunk_count)" -gt "$after" ] && break
    sleep 0.02
  done
  sleep "0.0$((RANDOM % 10))"
  target=$(pgrep -P "$pid" -x accelcal || true)
  [ -n "$target" ] || fail "round $round: the wizard had already ended"
  kill -9 $target
  wait "$pid" 2>/dev/null || true
}

before=""
for round in 1 2; do
  run_and_kill "$(( $(printf '%s' "$before" | grep -c . || true) + 20 + RANDOM % 30 ))" "$round"
  now=$(chunk_sums)
  [ "$(printf '%s\n' "$now" | grep -c .)" -gt "$(printf '%s' "$before" | grep -c . || true)" ] ||
    fail "round $round: no chunk was added"
  # Every chunk committed before this run is still there, unchanged (a prefix of the rows now).
  if [ -n "$before" ]; then
    [ "$(printf '%s\n' "$now" | head -n "$(printf '%s\n' "$before" | wc -l)")" = "$before" ] ||
      fail "round $round: a committed chunk changed or disappeared"
  fi
  before=$now
  [ "$round" -eq 1 ] || grep -q "Resuming the Static record for the drift analysis" "$work/out.$round" ||
    { cat "$work/out.$round" >&2; fail "round $round: no resume message"; }
done

run_wizard >"$work/final" 2>&1 || { tail "$work/final" >&2; fail "final run failed"; }
grep -q "Procedure complete" "$work/final" || { tail "$work/final" >&2; fail "not complete"; }
grep -q "gap of" "$work/final" || fail "the final run does not state its gap"
final_sums=$(chunk_sums)
[ "$(printf '%s\n' "$final_sums" | head -n "$(printf '%s\n' "$before" | wc -l)")" = "$before" ] ||
  fail "final run: a committed chunk changed or disappeared"

python3 - "$db" <<'PY' || fail "the record does not add up"
import sqlite3, sys
db = sqlite3.connect("file:" + sys.argv[1] + "?mode=ro", uri=True)
(t0, t1, n, chunks) = db.execute("SELECT min(t_first_s), max(t_last_s), sum(n), count(*) "
                                 "FROM record_chunks WHERE step_id = 'drift'").fetchone()
gaps = db.execute("SELECT t_start_s, t_end_s, reason, before_chunk FROM record_gaps "
                  "WHERE step_id = 'drift'").fetchall()
span = t1 - t0
gap_s = sum(e - s for s, e, _, _ in gaps)
print(f"span {span:.3f} s, {len(gaps)} gaps ({gap_s:.3f} s), {n} samples, {chunks} chunks")
assert 43200.0 <= span < 43200.0 + 0.01 + 1e-6, span
assert len(gaps) == 2, gaps
assert all(r == "resumed after interruption" and e > s for s, e, r, _ in gaps), gaps
# Each gap sits between two stored chunks: it starts at the last sample before it and ends at
# the first after it.
for s, e, _, k in gaps:
    prev_last, = db.execute("SELECT t_last_s FROM record_chunks WHERE step_id = 'drift' AND "
                            "chunk_index = ?", (k - 1,)).fetchone()
    next_first, = db.execute("SELECT t_first_s FROM record_chunks WHERE step_id = 'drift' AND "
                             "chunk_index = ?", (k,)).fetchone()
    assert (s, e) == (prev_last, next_first), (s, e, prev_last, next_first)
# The samples cover the span minus the gaps at 100 Hz: one interval less per run (3 runs).
recorded = span - gap_s
assert abs(n - (recorded * 100.0 + 3)) < 0.5 + 1e-6, (n, recorded)
state, = db.execute("SELECT state FROM session").fetchone()
outcome, = db.execute("SELECT outcome FROM steps_done WHERE step_id = 'drift'").fetchone()
assert state == "done", state
assert "2 gaps" in outcome, outcome
PY

# The other commands on a session of records: a listing, and clear refusals (no capture set,
# no calibration) rather than a crash.
"$accelcal" sessions "$db" >"$work/list" || fail "sessions"
grep -q " done " "$work/list" || { cat "$work/list"; fail "sessions: not done"; }
expect 1 "$accelcal" export "$db" -o "$work/c.csv"
grep -q "holds records (drift: 1[12] h [0-9]* min recorded over 12 h 0 min, 2 gaps" "$work/err" || { cat "$work/err"; fail "export message"; }
expect 1 "$accelcal" report "$db"
grep -q "holds records" "$work/err" || { cat "$work/err"; fail "report message"; }

# Every chunk of the record damaged (its stored size no longer matches: a bad copy): the Allan
# analysis refuses it by name; it was read as an empty record before.
cp "$db" "$work/damaged.db"
python3 - "$work/damaged.db" <<'PY'
import sqlite3, sys
db = sqlite3.connect(sys.argv[1])
db.execute("UPDATE record_chunks SET n = n + 1")
db.commit()
PY
expect 1 "$accelcal" allan "$work/damaged.db" -o "$work/damaged.allan.json"
grep -q "record 'drift': none of its [0-9]* stored chunks can be read" "$work/err" || { cat "$work/err"; fail "all-damaged message"; }
[ ! -e "$work/damaged.allan.json" ] || fail "an Allan file was written from a damaged record"
echo "ok"

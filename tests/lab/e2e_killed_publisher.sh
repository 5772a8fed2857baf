#!/usr/bin/env bash
# End to end: `accelcal lab publish` killed (kill -9) in the middle of publishing a backlog, again
# and again: the store never holds part of a session (every session row has its sensor,
# calibration, certificate and documents), the session files are never marked with a number the
# store does not hold, and the next publish finishes the backlog with no session twice.
# Kills are aimed (the publisher held, by a lock the test takes, inside its transaction after it
# drew a number) and at random instants; a kill inside a transaction is proven by the sequence: a number
# drawn and never used (the drawing transaction died with the process).
# Called by ctest as: e2e_killed_publisher.sh ACCELCAL SOURCE_DIR
set -euo pipefail
accelcal=$1 src=$2
source "$src/tests/lab/support.sh"
dir=$work/accelcal/sessions
mkdir -p "$dir"

"$accelcal" lab migrate >/dev/null
as_admin "CREATE ROLE bench_k LOGIN IN ROLE accelcal_bench"
export PGUSER=bench_k XDG_DATA_HOME=$work
sessions=16
for i in $(seq -w 1 $sessions); do
  "$make_session" "$dir/s$i.db" --device "K-$i" &
  [ $((10#$i % 4)) -ne 0 ] || wait
done
wait

whole() {  # nothing partial in the store
  local s c d
  s=$(sql "SELECT count(*) FROM accelcal.sessions")
  c=$(sql "SELECT count(*) FROM accelcal.sessions se JOIN accelcal.session_sensors USING (session_uuid)
           JOIN accelcal.calibrations USING (session_uuid, sensor_index)
           JOIN accelcal.certificates USING (session_uuid, sensor_index)")
  d=$(sql "SELECT count(*) FROM accelcal.certificate_documents")
  [ "$s" = "$c" ] && [ "$d" = $((2 * s)) ] || fail "partial: $s sessions, $c whole, $d documents"
  echo "$s"
}

# Holds the publisher inside its transaction after it drew a number: a superuser's transaction
# takes certificate_documents, which the publisher writes after drawing the number and rendering
# the certificate, so its INSERT waits on the lock with the number drawn and nothing committed.
# (Watching for that instant instead, as a first version did, misses it on an idle machine: the
# publisher is through it in well under a millisecond.)
hold_documents() {
  PGUSER=postgres "$PG_BIN/psql" -q -X -At -c "BEGIN; LOCK TABLE accelcal.certificate_documents IN ACCESS EXCLUSIVE MODE;
    SELECT pg_sleep(120); COMMIT;" >/dev/null 2>&1 &
  holder=$!
  local tries=0
  until [ "$(sql "SELECT count(*) FROM pg_locks l JOIN pg_class c ON c.oid = l.relation
                  WHERE c.relname = 'certificate_documents' AND l.mode = 'AccessExclusiveLock' AND l.granted")" -ge 1 ]; do
    tries=$((tries + 1)); [ "$tries" -lt 600 ] || fail "the lock on certificate_documents was never taken"
    sleep 0.05
  done
}
# Waits until the publisher's connection waits on that lock; fails when it closes first.
wait_blocked_on_documents() {
  pg_sql "SET statement_timeout = '60s'; DO \$\$
    BEGIN
      LOOP
        PERFORM pg_stat_clear_snapshot();
        IF EXISTS (SELECT 1 FROM pg_stat_activity WHERE usename = 'bench_k' AND wait_event_type = 'Lock'
                   AND query LIKE '%certificate_documents%') THEN RETURN; END IF;
        PERFORM pg_sleep(0.01);
      END LOOP;
    END \$\$" >/dev/null 2>&1
}
release_documents() {
  pg_sql "SELECT pg_terminate_backend(pid) FROM pg_stat_activity
          WHERE query LIKE '%pg_sleep(120)%' AND pid <> pg_backend_pid()" >/dev/null
  wait "$holder" 2>/dev/null || true
}

# Odd attempts kill the publisher while it is held inside a transaction (after drawing a number);
# even ones at a random instant (inside a transaction, between sessions, while writing a number
# back into a session file).
cut_inside=0
for attempt in $(seq 1 8); do
  before=$(whole)
  [ "$before" -lt "$sessions" ] || break
  [ $((attempt % 2)) -eq 0 ] || hold_documents
  "$accelcal" lab publish >"$work/publish.out" 2>&1 &
  pid=$!
  if [ $((attempt % 2)) -eq 1 ]; then
    wait_blocked_on_documents || true
  else
    sleep "0.$((RANDOM % 5))$((RANDOM % 10))"
  fi
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  [ $((attempt % 2)) -eq 0 ] || release_documents
  after=$(whole)
  drawn=$(sql "SELECT CASE WHEN is_called THEN last_value ELSE 0 END FROM accelcal.certificate_seq")
  [ "$drawn" -gt "$after" ] && cut_inside=1
  # Every number written into a session is one the store holds for that session.
  for f in "$dir"/*.db; do
    number=$(lab_number "$f")
    [ -z "$number" ] && continue
    [ "$(sql "SELECT count(*) FROM accelcal.certificates WHERE certificate_number = '$number'")" = 1 ] \
      || fail "$f carries $number, which the store does not hold"
  done
  [ "$cut_inside" = 1 ] && [ "$attempt" -ge 4 ] && break
done
[ "$cut_inside" = 1 ] || fail "no kill landed inside a publishing transaction in $attempt tries"

# The rest of the backlog, then nothing left; each session once, numbers distinct.
"$accelcal" lab publish >"$work/publish.out" 2>&1 || { cat "$work/publish.out"; fail "the final publish"; }
[ "$(whole)" = "$sessions" ] || fail "not every session is in the store"
[ "$(sql "SELECT count(DISTINCT certificate_number) FROM accelcal.certificates")" = "$sessions" ] || fail "numbers"
"$accelcal" lab publish | grep -q "nothing to publish" || fail "a backlog is left"
for f in "$dir"/*.db; do
  [ -n "$(lab_number "$f")" ] || fail "$f has no lab number"
done
echo "e2e_killed_publisher: ok (a kill landed inside a transaction: the sequence has drawn $(sql "SELECT last_value FROM accelcal.certificate_seq") numbers for $sessions certificates)"

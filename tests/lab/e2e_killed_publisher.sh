#!/usr/bin/env bash
# End to end: `accelcal lab publish` killed (kill -9) in the middle of publishing a backlog, again
# and again: the store never holds part of a session (every session row has its sensor,
# calibration, certificate and documents), the session files are never marked with a number the
# store does not hold, and the next publish finishes the backlog with no session twice.
# A kill is proven to have landed inside a transaction by the sequence: a number drawn and never
# used (the drawing transaction died with the process).
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

cut_inside=0
for attempt in $(seq 1 12); do
  before=$(whole)
  [ "$before" -lt "$sessions" ] || break
  "$accelcal" lab publish >"$work/publish.out" 2>&1 &
  pid=$!
  # A moment into the publishing (each session takes some tens of ms).
  sleep "0.$((RANDOM % 6 + 2))"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
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
  [ "$cut_inside" = 1 ] && [ "$attempt" -ge 3 ] && break
done
[ "$cut_inside" = 1 ] || fail "no kill landed inside a publishing transaction in 12 tries"

# The rest of the backlog, then nothing left; each session once, numbers distinct.
"$accelcal" lab publish >"$work/publish.out" 2>&1 || { cat "$work/publish.out"; fail "the final publish"; }
[ "$(whole)" = "$sessions" ] || fail "not every session is in the store"
[ "$(sql "SELECT count(DISTINCT certificate_number) FROM accelcal.certificates")" = "$sessions" ] || fail "numbers"
"$accelcal" lab publish | grep -q "nothing to publish" || fail "a backlog is left"
for f in "$dir"/*.db; do
  [ -n "$(lab_number "$f")" ] || fail "$f has no lab number"
done
echo "e2e_killed_publisher: ok (a kill landed inside a transaction: the sequence has drawn $(sql "SELECT last_value FROM accelcal.certificate_seq") numbers for $sessions certificates)"

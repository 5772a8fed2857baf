#!/usr/bin/env bash
# End to end, issue 33's "done when": two benches publish to one PostgreSQL lab store (a real
# server this script starts, pg_server.sh) at the same time, one of them offline part of the
# time; then the register's history, due dates and certificate numbers are checked, and what a
# bench and a lab manager may each do.
#   bench A reaches the server by its socket (PGHOST, PGUSER=bench_a);
#   bench B by TCP with a password, through a service file and a password file, as a bench
#   across the lab's network would (PGSERVICE, PGSERVICEFILE, PGPASSFILE): accelcal is given no
#   password anywhere.
# Sessions come from accelcal_make_session (backdated, for due dates) and one wizard run.
# Called by ctest as: e2e_two_benches.sh ACCELCAL SOURCE_DIR
set -euo pipefail
accelcal=$1 src=$2
source "$src/tests/lab/support.sh"

# expect CODE CMD...: runs CMD, checks its exit status, keeps stdout/stderr in $work/out, err.
expect() {
  local want=$1; shift
  set +e; "$@" >"$work/out" 2>"$work/err"; local got=$?; set -e
  [ "$got" -eq "$want" ] || { cat "$work/out" "$work/err" >&2; fail "'$*' exited $got, expected $want"; }
}

# The lab: its register made by its administrator (lab_admin, the database's owner), two
# benches and a lab manager.
expect 0 "$accelcal" lab migrate
grep -q "the register is at version" "$work/out" || fail "migrate said: $(cat "$work/out")"
as_admin "CREATE ROLE bench_a LOGIN IN ROLE accelcal_bench" \
  "CREATE ROLE bench_b LOGIN IN ROLE accelcal_bench PASSWORD 'b-secret-7'" \
  "CREATE ROLE mgr LOGIN IN ROLE accelcal_manager"

# A lab address that takes a connection and never answers (a wrong host behind a proxy or a
# firewall that swallows it): a socket that listens and never accepts. Its output to a file, so
# that a failure before it is stopped leaves ctest nothing to wait for.
python3 -c 'import socket, time
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(16)
print(s.getsockname()[1], flush=True); time.sleep(300)' >"$work/silent.port" 2>&1 &
silent_pid=$!
for _ in $(seq 50); do [ -s "$work/silent.port" ] && break; sleep 0.1; done
silent_port=$(cat "$work/silent.port")
[ -n "$silent_port" ] || fail "the silent listener did not start"

# Bench B's settings: a service file naming the lab (an unreachable one, for its time offline,
# and the silent one, with a long timeout) and its own password file (libpq requires 0600).
cat >"$work/services.conf" <<CONF
[lab]
host=127.0.0.1
port=$PG_TCP_PORT
dbname=lab
user=bench_b
connect_timeout=5
[lab-offline]
host=127.0.0.1
port=1
dbname=lab
user=bench_b
connect_timeout=5
[lab-silent]
host=127.0.0.1
port=$silent_port
dbname=lab
user=bench_b
connect_timeout=120
CONF
printf '127.0.0.1:%s:lab:bench_b:b-secret-7\n' "$PG_TCP_PORT" >"$work/pgpass"
chmod 600 "$work/pgpass"
bench_a() { env XDG_DATA_HOME="$work/a" PGUSER=bench_a "$@"; }
bench_b() {
  env -u PGHOST -u PGPORT -u PGDATABASE -u PGUSER XDG_DATA_HOME="$work/b" \
    PGSERVICEFILE="$work/services.conf" PGSERVICE="${B_SERVICE:-lab}" PGPASSFILE="${B_PASSFILE:-$work/pgpass}" "$@"
}
mgr() { env PGUSER=mgr "$@"; }

expect 0 bench_b "$accelcal" lab status
grep -q "role bench_b: accelcal_bench" "$work/out" || fail "bench B's status: $(cat "$work/out")"
grep -q "127.0.0.1:$PG_TCP_PORT" "$work/out" || fail "bench B not over TCP: $(cat "$work/out")"
# Without its password file bench B is refused by the server, and says so; no password is shown.
B_PASSFILE=$work/no-such-file expect 1 bench_b "$accelcal" lab status
grep -q "cannot reach the lab store (database lab on 127.0.0.1:$PG_TCP_PORT as bench_b)" "$work/err" || fail "no password: $(cat "$work/err")"
! grep -rq "b-secret-7" "$work/out" "$work/err" || fail "a password was shown"
# No accelcal option takes a password.
expect 2 "$accelcal" lab publish --password b-secret-7

# Sessions: each bench's directory, devices SIM-0001..3 over the past two years (dates relative
# to today, so the due dates below hold on any day).
day() { date -u -d "$1" +%Y-%m-%dT09:00:00.000Z; }
mkdir -p "$work/a/accelcal/sessions" "$work/b/accelcal/sessions"
n=0
for spec in "a SIM-0001 -700days" "a SIM-0002 -300days" "a SIM-0001 -200days" "a SIM-0003 -20days" \
            "b SIM-0001 -380days" "b SIM-0002 -100days" "b SIM-0003 -10days" "b SIM-0002 -30days"; do
  set -- $spec
  n=$((n + 1))
  "$make_session" "$work/$1/accelcal/sessions/s$n-$2.db" --device "$2" --date "$(day "$3")"
done
# One session from the wizard itself, on bench B while its lab's address does not answer (the
# silent service, whose own timeout is 120 s; device WIZ-0001, the rest the defaults): the
# terminal says what it waits for, the welcome that the lab cannot be reached and the session
# goes on, kept on the bench, the end that the session waits; the wizard waits its own 3 s
# twice, not the service's 120, and ends well.
start=$SECONDS
{ echo WIZ-0001; yes '' || true; } | B_SERVICE=lab-silent bench_b "$accelcal" wizard --source sim --speed 0 --plain \
  --session "$work/b/accelcal/sessions/wizard.db" >"$work/wizard.log" 2>&1 || { tail "$work/wizard.log"; fail "wizard"; }
wizard_s=$((SECONDS - start))
kill "$silent_pid" 2>/dev/null || true
(( wizard_s < 100 )) || fail "the wizard took $wizard_s s with a lab that does not answer"
head -1 "$work/wizard.log" | grep -q "^Checking the bench's equipment with the lab's register (waiting at most 3 s" \
  || fail "the wait is not said first: $(head -3 "$work/wizard.log")"
grep -q "The lab's register cannot be reached, so the equipment's calibration dates are not checked" "$work/wizard.log" \
  || fail "the offline welcome: $(head -20 "$work/wizard.log")"
grep -q "The session goes on here and is kept on this bench" "$work/wizard.log" || fail "the offline welcome's words"
grep -q "127.0.0.1:$silent_port as bench_b.*timeout expired" "$work/wizard.log" || fail "libpq's reason not said"
grep -q "^Sending the session to the lab's register (waiting at most 3 s" "$work/wizard.log" || fail "the end's wait not said"
grep -q "^The lab's register: wizard: not published: cannot reach the lab store.*it waits for \`accelcal lab publish\`" \
  "$work/wizard.log" || fail "the offline wizard's end: $(tail -5 "$work/wizard.log")"

# 1. Bench B is offline (its lab's address unreachable) while bench A publishes: B fails, says
#    its sessions wait, and publishes nothing.
bench_a "$accelcal" lab publish >"$work/a1.out" 2>&1 &
a1=$!
B_SERVICE=lab-offline expect 1 bench_b "$accelcal" lab publish
grep -q "cannot reach the lab store" "$work/err" || fail "offline B said: $(cat "$work/err")"
grep -q "5 session(s) wait, published by the next \`accelcal lab publish\`" "$work/err" || fail "offline B: $(cat "$work/err")"
wait $a1 || { cat "$work/a1.out"; fail "bench A's publish"; }
grep -q "^4 published, 0 already in the register, 0 not published" "$work/a1.out" || fail "bench A: $(cat "$work/a1.out")"
[ "$(sql "SELECT count(*) FROM accelcal.sessions")" = 4 ] || fail "4 sessions expected in the store"

# 2. The server goes away (stopped) while bench A has a new session: A fails and keeps it.
"$make_session" "$work/a/accelcal/sessions/s9-SIM-0003.db" --device SIM-0003 --date "$(day -1days)"
pg_stop
expect 1 bench_a "$accelcal" lab publish
grep -q "1 session(s) wait" "$work/err" || fail "A with the server down: $(cat "$work/err")"

# 3. The server is back: both benches catch up at the same time.
pg_restart
bench_a "$accelcal" lab publish >"$work/a3.out" 2>&1 &
a3=$!
bench_b "$accelcal" lab publish >"$work/b3.out" 2>&1 || { cat "$work/b3.out"; fail "bench B's catching up"; }
wait $a3 || { cat "$work/a3.out"; fail "bench A's catching up"; }
grep -q "^1 published" "$work/a3.out" || fail "A: $(cat "$work/a3.out")"
grep -q "^5 published" "$work/b3.out" || fail "B: $(cat "$work/b3.out")"
expect 0 bench_a "$accelcal" lab publish
grep -q "nothing to publish" "$work/out" || fail "A's backlog not empty: $(cat "$work/out")"

# Ten sessions, ten distinct numbers from the lab's sequence, each written back into its session
# and onto its certificate beside it, as the lab stored it.
[ "$(sql "SELECT count(*) FROM accelcal.sessions")" = 10 ] || fail "10 sessions expected"
[ "$(sql "SELECT count(DISTINCT certificate_number) FROM accelcal.certificates")" = 10 ] || fail "10 numbers expected"
[ "$(sql "SELECT count(*) FROM accelcal.sessions WHERE bench = 'bench_b'")" = 5 ] || fail "bench B's 5"
for f in "$work"/a/accelcal/sessions/*.db "$work"/b/accelcal/sessions/*.db; do
  number=$(lab_number "$f")
  [ -n "$number" ] || fail "$f: no lab number on its report"
  expect 0 "$accelcal" lab certificate "$number" -o "$work/cert.html"
  cmp -s "$work/cert.html" "${f%.db}.report.html" || fail "$f: the certificate beside it is not the lab's"
done

# Publishing again changes nothing.
expect 0 bench_a "$accelcal" lab publish "$work/a/accelcal/sessions/s1-SIM-0001.db"
grep -q "already in the lab's register as certificate LAB-" "$work/out" || fail "republish: $(cat "$work/out")"
[ "$(sql "SELECT count(*) FROM accelcal.sessions")" = 10 ] || fail "a republish added a row"

# History: SIM-0001's three calibrations from both benches, in date order.
expect 0 bench_b "$accelcal" lab history SIM-0001 --format json
jq -e '.device == "SIM-0001" and (.calibrations | length) == 3' "$work/out" >/dev/null || fail "history: $(cat "$work/out")"
jq -e '[.calibrations[].bench] == ["bench_a", "bench_b", "bench_a"]' "$work/out" >/dev/null || fail "history benches"
jq -e '[.calibrations[].date_utc] == ([.calibrations[].date_utc] | sort)' "$work/out" >/dev/null || fail "history order"
jq -e 'all(.calibrations[]; (.certificate_number | test("^LAB-[0-9]{6}$")) and .status == "issued"
       and (.session | length) > 0 and (.verdict | length) > 0)' "$work/out" >/dev/null || fail "history fields"
newest=$(jq -r '.calibrations[2].certificate_number' "$work/out")
expect 0 bench_a "$accelcal" lab history WIZ-0001 --format json
jq -e '.calibrations[0].verdict == "PASS" and .calibrations[0].bench == "bench_b" and .calibrations[0].session == "wizard"' \
  "$work/out" >/dev/null || fail "the wizard's session: $(cat "$work/out")"
oldest=$(jq -r '.calibrations[0].certificate_number' "$work/out")

# Roles: a bench cannot approve or withdraw (the database refuses); a lab manager can; the
# withdrawn certificate stays in the history.
expect 1 bench_a "$accelcal" lab approve "$newest"
grep -q "refused.*permission denied for table certificates" "$work/err" || fail "bench approve: $(cat "$work/err")"
expect 1 bench_b "$accelcal" lab withdraw "$oldest" --reason "mine"
expect 0 mgr "$accelcal" lab approve "$newest"
expect 0 mgr "$accelcal" lab withdraw "$newest" --reason "turntable out of calibration"
expect 1 mgr "$accelcal" lab approve "$newest"
grep -q "stays withdrawn" "$work/err" || fail "re-approve: $(cat "$work/err")"
expect 0 bench_a "$accelcal" lab history SIM-0001
grep -q "^$newest .* withdrawn .*bench_a" "$work/out" || fail "withdrawn not in history: $(cat "$work/out")"
grep -q "withdrawn .* by mgr: turntable out of calibration" "$work/out" || fail "withdrawal reason: $(cat "$work/out")"
[ "$(sql "SELECT count(*) FROM accelcal.certificates")" = 10 ] || fail "a certificate went missing"

# Due: SIM-0001's last valid calibration is now bench B's, 380 days ago (bench A's of 200 days
# ago is withdrawn): overdue by 15 days at the lab's default 365; SIM-0002's (30 days ago) is not due within 30
# days, nor SIM-0003's. With a 60-day interval for its type, SIM-0002 is due in 30 days.
expect 0 bench_a "$accelcal" lab due --within 30d --format json
jq -e '[.due[] | select(.kind == "device") | .id] == ["SIM-0001"] and .due[0].days_left == -15' "$work/out" >/dev/null \
  || fail "due: $(cat "$work/out")"
expect 0 mgr "$accelcal" lab device-type MMA7260Q --interval 60d
expect 0 mgr "$accelcal" lab device SIM-0002 --type MMA7260Q
expect 1 bench_a "$accelcal" lab device SIM-0002 --type MMA7260Q
expect 0 bench_a "$accelcal" lab due --within 30d
grep -q "^device .*SIM-0002 .*due in 30 day(s)" "$work/out" || fail "due after the interval: $(cat "$work/out")"

# Equipment: a turntable whose certificate ran out and a ruler in date; the welcome's check.
expect 0 mgr "$accelcal" lab equipment add TT-01 --kind turntable --name "Turntable A" --certificate CAL-17 \
  --calibrated "$(date -u -d -400days +%F)" --valid-until "$(date -u -d -35days +%F)"
expect 0 mgr "$accelcal" lab equipment add RUL-01 --kind ruler --name "Steel ruler" --certificate CAL-18 \
  --calibrated "$(date -u -d -10days +%F)" --valid-until "$(date -u -d +355days +%F)"
expect 1 bench_a "$accelcal" lab equipment add LVL-01 --kind level --name L --certificate C \
  --calibrated 2026-01-01 --valid-until 2027-01-01
expect 1 bench_a "$accelcal" lab equipment --check TT-01 RUL-01 NOPE-1
grep -q "turntable TT-01: its calibration expired on" "$work/out" || fail "check: $(cat "$work/out")"
grep -q "NOPE-1: not in the lab's equipment register" "$work/out" || fail "check unknown: $(cat "$work/out")"
expect 0 bench_a "$accelcal" lab equipment --check RUL-01
expect 0 bench_b "$accelcal" lab equipment
grep -q "^TT-01 .*EXPIRED 35 day(s) ago" "$work/out" || fail "equipment list: $(cat "$work/out")"
expect 0 bench_a "$accelcal" lab due --within 30d
grep -q "^equipment .*TT-01 .*overdue by 35 day(s)" "$work/out" || fail "equipment due: $(cat "$work/out")"
# The wizard on bench A, online, with the expired turntable and the ruler named at its welcome:
# warned there of the turntable (not of the ruler), and its session published at its end.
{ echo WIZ-0002; echo; echo; echo; echo "turntable id TT-01; ruler id RUL-01"; yes '' || true; } |
  bench_a "$accelcal" wizard --source sim --speed 0 --plain --session "$work/a/accelcal/sessions/wizard-a.db" \
  >"$work/wizard-a.log" 2>&1 || { tail "$work/wizard-a.log"; fail "wizard on bench A"; }
grep -q "Equipment: turntable TT-01: its calibration expired on" "$work/wizard-a.log" \
  || fail "no warning of the expired turntable: $(head -30 "$work/wizard-a.log")"
# (The virtual bench's own items, SIM-RUL-01 and the rest, offered before the answer, are unknown
# to this lab and said so: only the ruler named RUL-01 is in date.)
! grep -qE '(^|[ (])RUL-01:' "$work/wizard-a.log" || fail "the ruler in date was warned of"
grep -q "^The lab's register: wizard-a: published as certificate LAB-[0-9]\{6\}$" "$work/wizard-a.log" \
  || fail "the wizard's end: $(tail -5 "$work/wizard-a.log")"
expect 0 bench_a "$accelcal" lab history WIZ-0002 --format json
jq -e '(.calibrations | length) == 1 and .calibrations[0].bench == "bench_a"' "$work/out" >/dev/null || fail "WIZ-0002: $(cat "$work/out")"
[ "$(lab_number "$work/a/accelcal/sessions/wizard-a.db")" = "$(jq -r '.calibrations[0].certificate_number' "$work/out")" ] \
  || fail "the wizard's session does not carry its lab number"
# --no-lab: neither the check nor the publishing.
{ echo WIZ-0003; yes '' || true; } | bench_a "$accelcal" wizard --no-lab --source sim --speed 0 --plain \
  --session "$work/a/accelcal/sessions/wizard-c.db" >"$work/wizard-c.log" 2>&1 || fail "wizard --no-lab"
! grep -q "lab's" "$work/wizard-c.log" || fail "--no-lab reached the lab: $(grep "lab's" "$work/wizard-c.log")"
[ "$(sql "SELECT count(*) FROM accelcal.sessions WHERE name = 'wizard-c'")" = 0 ] || fail "--no-lab published"
echo "e2e_two_benches: ok"

#!/usr/bin/env bash
# End to end: a session whose writer was killed in the middle of a transaction in rollback-journal
# mode (the wizard's clean close switches the file to one: a kill -9 then leaves a hot journal
# beside it; seen as a rare failure of wizard_resume.sh). The read-only commands used to call it
# "not an accelcal session (... attempt to write a readonly database)"; they must read it as its
# last committed state: every capture there, the journal rolled back. Called by ctest as:
#   session_interrupted_write.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
: "$data"
make_session=$(dirname "$accelcal")/accelcal_make_session
source "$src/tests/e2e/lib/common.bash"
command -v python3 >/dev/null || { echo "python3 missing: skipped"; exit 77; }

"$make_session" "$work/s.db"
expect 0 "$accelcal" sessions "$work/s.db"
grep -Eq ' 18 done +yes$' "$work/out" || { cat "$work/out"; fail "the made session is not finished"; }

# A writer that deletes every capture, its pages spilled to the file before the commit, then
# dies by kill -9: the file holds the half-done write, the journal the committed pages.
python3 - "$work/s.db" <<'PY'
import os, sqlite3, sys
child = os.fork()
if child == 0:  # the writer, killed mid-transaction
    db = sqlite3.connect(sys.argv[1], isolation_level=None)
    db.execute("PRAGMA journal_mode = DELETE")
    db.execute("PRAGMA cache_size = 2")
    db.execute("BEGIN")
    db.execute("DELETE FROM captures")
    os.kill(os.getpid(), 9)
_, status = os.waitpid(child, 0)
sys.exit(0 if os.WIFSIGNALED(status) and os.WTERMSIG(status) == 9 else 1)
PY
[ -s "$work/s.db-journal" ] || fail "no hot journal was left: the test did not interrupt a write"

expect 0 "$accelcal" sessions "$work/s.db"
grep -Eq ' 18 done +yes$' "$work/out" || { cat "$work/out"; fail "sessions: not the committed state"; }
grep -q "unreadable" "$work/out" && fail "sessions: the session called unreadable"
[ -e "$work/s.db-journal" ] && fail "the hot journal was not rolled back"
expect 0 "$accelcal" export "$work/s.db" -o "$work/c.csv"
[ "$(grep -v '^#' "$work/c.csv" | tail -n +2 | cut -d, -f1 | uniq | wc -l)" -eq 18 ] ||
  fail "export: not the 18 captures"
expect 0 "$accelcal" report "$work/s.db"
grep -q "^2. Parameters (1-sigma uncertainties)$" "$work/out" || fail "report"
echo "session_interrupted_write: ok"

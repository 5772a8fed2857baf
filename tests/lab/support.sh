# What the lab store's end-to-end scripts share (sourced after `accelcal=... src=...`): a private
# server started (pg_server.sh) with a work directory inside it, and small helpers.
#   fail MSG          the test's failure
#   sql SQL           one value, as the superuser
#   as_admin SQL...   statements as the lab's administrator (lab_admin)
#   lab_number FILE   the lab's certificate number on a session's report ("" when none)
source "$src/tests/lab/pg_server.sh"
make_session=$(dirname "$accelcal")/accelcal_make_session
fail() { echo "FAIL: $*" >&2; exit 1; }
pg_start
work=$PG_DIR/work
mkdir -p "$work"
sql() { pg_sql "$1" | sed 's/^ *//'; }
as_admin() {
  local args=()
  for statement in "$@"; do args+=(-c "$statement"); done
  PGUSER=lab_admin "$PG_BIN/psql" -q -X -v ON_ERROR_STOP=1 "${args[@]}"
}
lab_number() {
  "$accelcal" report "$1" >"$work/report.txt"
  sed -n 's/.*Certificate No\.[ :]*\(LAB-[0-9]*\).*/\1/p' "$work/report.txt" | sed -n 1p
}

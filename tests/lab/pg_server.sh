# A private PostgreSQL server for the lab store's tests (sourced by the scripts here): a cluster
# made by initdb in a temporary directory, started by pg_ctl on a free port of 127.0.0.1 and a
# socket in that directory, stopped and removed when the script exits (trap). Debian's
# postgresql package provides the server (scripts/setup.sh installs it with the tests' packages).
#
# PostgreSQL refuses to run as root: as root (CI), the server runs as the user `postgres` that
# Debian's package creates for it (runuser); as anyone else, as that user. The client side (the
# tests, accelcal) runs as the caller and reaches the server by its socket or by TCP.
#
# After pg_start:
#   PGHOST (the socket directory), PGPORT, PGDATABASE=lab, PGUSER=lab_admin are exported:
#   lab_admin owns the database `lab` and has CREATEROLE, as a lab's administrator would, and
#   CREATEDB (the C++ tests make a database per test); not a
#   superuser: a superuser bypasses row-level security, and the tests check it);
#   pg_sql SQL           runs SQL as the superuser, rows unaligned;
#   pg_stop / pg_restart stop and start the same cluster (a lab server going away and back);
#   PG_TCP_PORT          the server's TCP port (password authentication, scram-sha-256).
# Socket connections are trusted (any role by name: what each role may do is the point of the
# tests, not who it is); TCP ones need a password, for the ~/.pgpass and service-file tests.

pg_bin_dir() {
  local d
  for d in $(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V -r); do
    [ -x "$d/initdb" ] && [ -x "$d/pg_ctl" ] && { echo "$d"; return 0; }
  done
  return 1
}

pg_run() {  # runs a server tool as the server's user
  if [ -n "${PG_RUN_AS:-}" ]; then runuser -u "$PG_RUN_AS" -- "$@"; else "$@"; fi
}

pg_start() {
  PG_BIN=$(pg_bin_dir) || { echo "FAIL: no PostgreSQL server (Debian's postgresql package; scripts/setup.sh installs it)"; exit 1; }
  PG_RUN_AS=""
  if [ "$(id -u)" -eq 0 ]; then
    getent passwd postgres >/dev/null || { echo "FAIL: running as root and there is no user postgres to run the server as (Debian's postgresql package creates it)"; exit 1; }
    PG_RUN_AS=postgres
  fi
  PG_DIR=$(mktemp -d /tmp/accelcal-pg.XXXXXX)
  chmod 755 "$PG_DIR"
  [ -z "$PG_RUN_AS" ] || chown "$PG_RUN_AS" "$PG_DIR"
  trap pg_cleanup EXIT
  pg_run "$PG_BIN/initdb" -N -D "$PG_DIR/data" -U postgres --auth-local=trust --auth-host=scram-sha-256 \
    -E UTF8 --locale=C.UTF-8 >"$PG_DIR/initdb.log" 2>&1 || { cat "$PG_DIR/initdb.log"; echo "FAIL: initdb"; exit 1; }
  mkdir -p "$PG_DIR/sock"
  [ -z "$PG_RUN_AS" ] || chown "$PG_RUN_AS" "$PG_DIR/sock"
  # A free port: tried until one starts (another test may hold the one drawn).
  local attempt
  for attempt in 1 2 3 4 5 6 7 8; do
    PG_TCP_PORT=$((20000 + (RANDOM * 7 + $$ + attempt * 131) % 30000))
    if pg_run "$PG_BIN/pg_ctl" -D "$PG_DIR/data" -l "$PG_DIR/server.log" -w -t 60 start \
        -o "-p $PG_TCP_PORT -k $PG_DIR/sock -c listen_addresses=127.0.0.1 -c fsync=off -c full_page_writes=off -c synchronous_commit=off -c max_connections=60" \
        >/dev/null 2>&1; then
      break
    fi
    PG_TCP_PORT=""
  done
  [ -n "$PG_TCP_PORT" ] || { cat "$PG_DIR/server.log"; echo "FAIL: the test server did not start"; exit 1; }
  export PGHOST="$PG_DIR/sock" PGPORT="$PG_TCP_PORT"
  unset PGSERVICE PGSERVICEFILE PGPASSFILE PGPASSWORD PGHOSTADDR PGOPTIONS
  PGDATABASE=postgres PGUSER=postgres "$PG_BIN/psql" -q -X -v ON_ERROR_STOP=1 \
    -c "CREATE ROLE lab_admin LOGIN CREATEROLE CREATEDB" -c "CREATE DATABASE lab OWNER lab_admin" >/dev/null \
    || { echo "FAIL: could not create the lab's database"; exit 1; }
  export PGDATABASE=lab PGUSER=lab_admin
}

pg_sql() { PGUSER=postgres "$PG_BIN/psql" -q -X -v ON_ERROR_STOP=1 -At -c "$1"; }

pg_stop() { pg_run "$PG_BIN/pg_ctl" -D "$PG_DIR/data" -w -m fast stop >/dev/null; }
pg_restart() {
  pg_run "$PG_BIN/pg_ctl" -D "$PG_DIR/data" -l "$PG_DIR/server.log" -w -t 60 start \
    -o "-p $PG_TCP_PORT -k $PG_DIR/sock -c listen_addresses=127.0.0.1 -c fsync=off -c full_page_writes=off -c synchronous_commit=off -c max_connections=60" >/dev/null
}

pg_cleanup() {
  if [ -n "${PG_DIR:-}" ] && [ -d "$PG_DIR" ]; then
    [ -f "$PG_DIR/data/postmaster.pid" ] && pg_run "$PG_BIN/pg_ctl" -D "$PG_DIR/data" -w -m immediate stop >/dev/null 2>&1
    rm -rf "$PG_DIR"
  fi
}

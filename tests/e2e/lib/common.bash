# Shared by the end-to-end scripts (sourced; not a test itself). Sets `work` to a fresh
# directory removed on exit, and defines:
#   fail MSG...          print "FAIL: MSG" on stderr and exit 1
#   expect CODE CMD...   run CMD, require exit status CODE; its stdout/stderr stay in
#                        $work/out and $work/err for the checks that follow
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

expect() {
  local want=$1; shift
  set +e; "$@" >"$work/out" 2>"$work/err"; local got=$?; set -e
  [ "$got" -eq "$want" ] || { cat "$work/err" >&2; fail "'$*' exited $got, expected $want"; }
}

# start_silent_server MODE SECONDS: lib/silent_server.py in the background; sets $server (its
# pid) and $port. stop_silent_server ends it.
start_silent_server() {
  python3 "$source_dir/tests/e2e/lib/silent_server.py" "$1" "$2" > "$work/port" &
  server=$!
  for _ in $(seq 50); do [ -s "$work/port" ] && break; sleep 0.1; done
  port=$(head -1 "$work/port")
  [ -n "$port" ] || fail "$1: the test server did not start"
}
stop_silent_server() {
  kill "$server" 2>/dev/null || true
  wait "$server" 2>/dev/null || true
  rm -f "$work/port"
}

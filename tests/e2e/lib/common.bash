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

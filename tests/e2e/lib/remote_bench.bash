# The virtual bench behind a real link, for the device end-to-end scripts (sourced after
# common.bash and clumsy.bash, with `accelcal` and `source_dir` set). One process group plays the
# device: `accelcal record --source sim --bench-listen` streams the bench as text lines and serves
# its controls; a peer turns the lines into what the link carries (TCP text, a MAVLink vehicle,
# an IIO device). The wizard reads the link and places the sensor through --bench-control.
#
#   start_bench SPEED PEER...   starts `record | PEER...` in its own process group (the bench
#                               of scenario $bench_scenario when set, else the default); sets
#                               $bench_port (the controls), $peer_port (the peer's first line
#                               "port N", when it prints one) and $bench_group; the peer's
#                               stderr in $work/peer.err, record's in $work/bench.err
#   stop_bench                  ends that process group (and only it)
#   bench_wizard ANSWERS SOURCE DB PROCEDURE [ARGS...]   the wizard on SOURCE: the ANSWERS
#                               (printf-style; a new session's serial and operator) then those
#                               of `yes ''`; output in $work/out; status checked
#   bench_wizard_killed ANSWERS TEXT SOURCE DB PROCEDURE [ARGS...]   the same in the background,
#                               kill -9 once its output says TEXT (a step done mid-session)
#   quiet_scenario FILE         writes FILE: the default bench with a quiet sensor (about 0.9 mG
#                               of noise) behind a 16-bit ADC (steps of 1.8e-3 m/s^2, 16 times
#                               finer than the default's, so the ADC's own rounding stays below
#                               the noise); a vehicle streams it with --scale 556.8 --bias 32768
start_bench() {
  local speed=$1; shift
  rm -f "$work/peer.port" "$work/bench.err"
  setsid bash -c '"$0" record --source sim --speed "$1" --seed 7 ${3:+--scenario "$3"} \
      --bench-listen 127.0.0.1:0 -o - 2>"$2/bench.err" | "${@:4}" >"$2/peer.port" 2>"$2/peer.err"' \
    "$accelcal" "$speed" "$work" "${bench_scenario:-}" "$@" &
  bench_group=$!
  for _ in $(seq 100); do
    grep -q "bench controls at port" "$work/bench.err" 2>/dev/null && [ -s "$work/peer.port" ] && break
    sleep 0.1
  done
  bench_port=$(sed -n 's/.*bench controls at port \([0-9]*\).*/\1/p' "$work/bench.err" | head -1)
  peer_port=$(sed -n 's/^port \([0-9]*\)$/\1/p' "$work/peer.port" | head -1)
  [ -n "$bench_port" ] || { cat "$work/bench.err" "$work/peer.err" >&2; fail "the bench did not start"; }
}

stop_bench() {
  [ -n "${bench_group:-}" ] || return 0
  kill -- "-$bench_group" 2>/dev/null || true
  wait "$bench_group" 2>/dev/null || true
  bench_group=
}

bench_wizard() {  # ANSWERS SOURCE DB PROCEDURE [ARGS...]
  local answers=$1 source=$2 db=$3 procedure=$4; shift 4
  set +e
  { printf "$answers"; yes ''; } | timeout 900 "$accelcal" wizard --source "$source" \
    --bench-control "127.0.0.1:$bench_port" --procedure "$procedure" --session "$db" --plain "$@" \
    > "$work/out" 2> "$work/err"
  local code=${PIPESTATUS[1]}
  set -e
  [ "$code" -eq 0 ] || { tail -30 "$work/out" >&2; cat "$work/err" >&2; fail "wizard on $source exited $code"; }
}

bench_wizard_killed() {  # ANSWERS TEXT SOURCE DB PROCEDURE [ARGS...]
  local answers=$1 text=$2 source=$3 db=$4 procedure=$5; shift 5
  { printf "$answers"; yes ''; } | "$accelcal" wizard --source "$source" \
    --bench-control "127.0.0.1:$bench_port" --procedure "$procedure" --session "$db" --plain "$@" \
    > "$work/out.killed" 2>&1 &
  local pid=$!  # the last command of the pipeline: accelcal itself
  for _ in $(seq 1200); do
    flat "$work/out.killed" "$text" && break
    kill -0 "$pid" 2>/dev/null || { tail -20 "$work/out.killed" >&2; fail "the wizard ended before: $text"; }
    sleep 0.1
  done
  flat "$work/out.killed" "$text" || fail "the wizard never said: $text"
  kill -9 "$pid"
  wait "$pid" 2>/dev/null || true
}

quiet_scenario() {  # FILE
  sed -e 's/^bias_counts = .*/bias_counts = [32820.8, 32633.6, 33004.8]/' \
      -e 's/^scale_counts_per_mps2 = .*/scale_counts_per_mps2 = [553.92, 561.12, 550.56]/' \
      -e 's/^noise_counts = .*/noise_counts = [4.8, 4.8, 4.8]/' \
      -e 's/^bits = 12 .*/bits = 16/' \
      "$source_dir/scenarios/bench_default.toml" > "$1"
  [ "$(grep -c '^bias_counts = \[32820.8\|^scale_counts_per_mps2 = \[553.92\|^noise_counts = \[4.8\|^bits = 16$' "$1")" -eq 4 ] \
    || fail "quiet scenario: the default bench's lines were not found"
}

# Checks of a several-sensor session (issue 31), for the fixture end-to-end scripts (sourced
# after common.bash, with `accelcal`, `db` and `work` set).
#   captures_of SENSOR [KIND]       how many captures the session $db holds of sensor SENSOR
#                                   (1-based; of that kind: static, turntable)
#   sensor_within_truth N LABEL K   sensor N's calibration from $db (written to $work/cal_N.json)
#                                   within K sigma of $work/truth_N.json (a calibration-shaped
#                                   JSON: bias_counts, scale_counts_per_mps2, misalignment_rad);
#                                   else prints both and fails, naming LABEL
#   board_truth SCENARIO SERIAL     the virtual bench's board SERIAL of SCENARIO's [fixture], its
#                                   stated truth as a calibration-shaped JSON (for
#                                   sensor_within_truth's $work/truth_N.json)
#   sensor_report_checked STEM SERIAL  the report the wizard wrote beside the session
#                                   ($work/STEM.SERIAL.report.txt) is there and names SERIAL;
#                                   its certificate number is added to $work/numbers (check
#                                   afterwards that they differ)
#   wizard_on_enter ARGS...         `accelcal wizard ARGS... --plain`, every answer Enter, its
#                                   output in $work/out and $work/err; fails with both when it
#                                   exits other than 0
#   [REPORT_ARGS=(...)]             more arguments for `accelcal report` (a --procedure)
#   kill_at_step PID OUT STEP       waits (up to 2 min) until the wizard PID's output OUT shows
#                                   step STEP (`[STEP/`), where it waits for an answer it was not
#                                   given, then kill -9; fails when it ended before

captures_of() {
  "$accelcal" export "$db" --sensor "$1" -o "$work/export_$1.csv" > /dev/null
  grep -v '^#' "$work/export_$1.csv" | tail -n +2 | awk -F, -v k="${2:-}" 'k == "" || $2 == k' |
    cut -d, -f1 | uniq | wc -l
}

sensor_within_truth() {  # N LABEL K
  local n=$1 label=$2 k=$3
  "$accelcal" report "$db" --sensor "$n" ${REPORT_ARGS[@]+"${REPORT_ARGS[@]}"} --format calibration \
    -o "$work/cal_$n.json" > /dev/null || fail "no calibration of $label"
  jq -e --argjson k "$k" --slurpfile t "$work/truth_$n.json" '
    def z(v; s; w): ((v - w) / s) | fabs;
    [range(3) as $i | z(.bias_counts[$i]; .uncertainty.bias_counts[$i]; $t[0].bias_counts[$i]),
                      z(.scale_counts_per_mps2[$i]; .uncertainty.scale_counts_per_mps2[$i];
                        $t[0].scale_counts_per_mps2[$i])]
    + [z(.misalignment_rad.yz; .uncertainty.misalignment_rad.yz; $t[0].misalignment_rad.yz),
       z(.misalignment_rad.zy; .uncertainty.misalignment_rad.zy; $t[0].misalignment_rad.zy),
       z(.misalignment_rad.zx; .uncertainty.misalignment_rad.zx; $t[0].misalignment_rad.zx)]
    | max < $k' "$work/cal_$n.json" > /dev/null || {
    jq -c '{bias_counts, scale_counts_per_mps2, misalignment_rad, uncertainty}' "$work/cal_$n.json" >&2
    cat "$work/truth_$n.json" >&2
    fail "$label: more than $k sigma from its truth"
  }
}

board_truth() {  # SCENARIO SERIAL
  awk -v s="\"$2\"" '
    $1 == "serial" && $3 == s { on = 1; next }
    on && /^\[\[fixture.board\]\]/ { exit }
    on && /^bias_counts/ { sub(/^[^=]*= */, ""); b = $0 }
    on && /^scale_counts_per_mps2/ { sub(/^[^=]*= */, ""); k = $0 }
    on && /^misalignment_rad/ { sub(/^[^=]*= */, ""); m = $0 }
    END { gsub(/=/, ":", m); gsub(/yz/, "\"yz\"", m); gsub(/zy/, "\"zy\"", m); gsub(/zx/, "\"zx\"", m);
          printf "{\"bias_counts\": %s, \"scale_counts_per_mps2\": %s, \"misalignment_rad\": %s}\n", b, k, m }
  ' "$1"
}

sensor_report_checked() {  # STEM SERIAL
  local report="$work/$1.$2.report.txt"
  [ -s "$report" ] || fail "no report of $2"
  grep -q "$2" "$report" || fail "$2's report does not name it"
  sed -n 's/.*Certificate No.: *\(ACC-[^ ]*\).*/\1/p' "$report" >> "$work/numbers"
}

wizard_on_enter() {  # ARGS...
  set +e
  yes '' | "$accelcal" wizard "$@" --plain > "$work/out" 2> "$work/err"
  local code=${PIPESTATUS[1]}
  set -e
  [ "$code" -eq 0 ] || { tail -20 "$work/out" >&2; cat "$work/err" >&2; fail "wizard $* exited $code"; }
}

kill_at_step() {  # PID OUT STEP
  local pid=$1 out=$2 step=$3
  for _ in $(seq 12000); do
    grep -q "^\[$step/" "$out" 2>/dev/null && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
  done
  kill -0 "$pid" 2>/dev/null || { cat "$out" >&2; fail "the first run ended before it was killed"; }
  grep -q "^\[$step/" "$out" || { cat "$out" >&2; fail "the first run never reached step $step"; }
  kill -9 "$pid"
  wait "$pid" 2>/dev/null || true
}

# Shared by the clumsy-bench end-to-end scripts (sourced after common.bash, with `accelcal` and
# `source_dir` set). Each script plays one fault of scenarios/clumsy_*.toml through the wizard
# in line mode and checks what the technician is told and that no wrong calibration passes.
#
#   short_procedure            writes $work/short.toml: the seed procedure with 3 s captures
#                              (the checks are the same; CI time is not)
#   wizard SCENARIO DB ANSWERS [FLAGS...]  runs the wizard on the sim at speed 0 with the answers given
#                              (one per line, printf-style) and then empty ones; output in
#                              $work/out, status checked (a wizard not ended in 200 s fails:
#                              a screen that answers Enter with itself). SCENARIO: a file of
#                              scenarios/, or a path (one holding a '/'); FLAGS: more of the wizard's
#                              options. Exit status 0 expected; `expect_exit=1 wizard ...` for a
#                              session that ends at a dead end (a refused fit: saved, failed)
#   calibration DB             writes $work/cal.json, the session's calibration
#   within_truth K             every parameter of $work/cal.json within K sigma of the default
#                              bench's truth (scenarios/bench_default.toml); else prints them
#   said TEXT                  $work/out holds TEXT (fixed string; runs of blanks and line
#                              breaks read as one blank, so wrapped lines match)
#   flat FILE TEXT             the same for any FILE (status only)

short_procedure() {
  sed -e 's/^capture_duration_s = 10 /capture_duration_s = 3 /' \
    "$source_dir/procedures/full_calibration.toml" > "$work/short.toml"
  grep -q '^capture_duration_s = 3 ' "$work/short.toml" || fail "short procedure: no capture_duration_s"
}

wizard() {  # SCENARIO DB ANSWERS [OPTION...]
  local scenario=$1 db=$2 answers=$3
  shift 3
  case "$scenario" in */*) ;; *) scenario=$source_dir/scenarios/$scenario ;; esac
  set +e
  # The answers end in Enter for ever: a screen that answers Enter with itself would go round
  # until ctest's timeout; the limit says so instead (wizard_way_back's effects_demo part did).
  { printf "$answers"; yes ''; } | timeout 200 "$accelcal" wizard --source sim --speed 0 \
    --scenario "$scenario" --procedure "$work/short.toml" --session "$db" \
    --plain "$@" > "$work/out" 2> "$work/err"
  local code=${PIPESTATUS[1]}
  set -e
  if [ "$code" -eq 124 ]; then
    grep -v '^> *$' "$work/out" | tail -20 >&2
    fail "the wizard did not end in 200 s: a screen answered Enter with itself (a loop)"
  fi
  local want=${expect_exit:-0}
  [ "$code" -eq "$want" ] || { tail -20 "$work/out" >&2; cat "$work/err" >&2; fail "wizard exited $code, not $want"; }
}

calibration() { "$accelcal" report "$1" --format calibration -o "$work/cal.json" > /dev/null; }

within_truth() {  # K
  jq -e --argjson k "$1" '
    def z(v; s; t): ((v - t) / s) | fabs;
    [z(.bias_counts[0]; .uncertainty.bias_counts[0]; 2051.3),
     z(.bias_counts[1]; .uncertainty.bias_counts[1]; 2039.6),
     z(.bias_counts[2]; .uncertainty.bias_counts[2]; 2062.8),
     z(.scale_counts_per_mps2[0]; .uncertainty.scale_counts_per_mps2[0]; 34.62),
     z(.scale_counts_per_mps2[1]; .uncertainty.scale_counts_per_mps2[1]; 35.07),
     z(.scale_counts_per_mps2[2]; .uncertainty.scale_counts_per_mps2[2]; 34.41),
     z(.misalignment_rad.yz; .uncertainty.misalignment_rad.yz; 0.0042),
     z(.misalignment_rad.zy; .uncertainty.misalignment_rad.zy; -0.0031),
     z(.misalignment_rad.zx; .uncertainty.misalignment_rad.zx; 0.0057)] | max < $k' \
    "$work/cal.json" > /dev/null || {
    jq -c '{bias_counts, scale_counts_per_mps2, misalignment_rad, uncertainty}' "$work/cal.json" >&2
    fail "the calibration is more than $1 sigma from the truth"
  }
}

said() {
  flat "$work/out" "$1" || { tail -30 "$work/out" >&2; fail "never said: $1"; }
}

# flat FILE TEXT: FILE holds TEXT, blanks and line breaks read as one blank. Never `producer |
# grep -q`: under pipefail, grep leaving at the first match can kill the producer with SIGPIPE
# and fail a check that matched, depending on how the two processes are scheduled.
flat() {
  tr -s ' \n' '  ' < "$1" > "$1.flat"
  grep -qF -- "$2" "$1.flat"
}

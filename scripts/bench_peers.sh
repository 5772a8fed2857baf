#!/usr/bin/env bash
# Side-by-side speed of accelcal and its peer tools as whole processes (issue 18).
#
#   scripts/bench_peers.sh [--accelcal PATH] [--peers DIR] [--imu-tk-acc CMD] [--allantools CMD]
#                          [--hours H] [--rate-hz R] [--read-hours H] [--runs N]
#                          [--allan-runs N] [--reps N] [--xsens FILE] [--workdir DIR]
#                          [--accelcal-bench PATH]
#
# The peers are built from their public sources, outside the repository, by
# scripts/bench_peers_build.sh; --peers DIR takes the two it built in DIR. They can also be any
# commands given as options or environment variables (below). A peer not given is said and its
# rows are skipped.
#   IMU_TK_ACC_CMD  (--imu-tk-acc)  runs imu_tk's accelerometer calibration alone
#       (MultiPosCalibration::calibrateAcc with the settings of imu_tk's apps/test_imu_calib.cpp
#       for the Xsens data: init static 50 s, 100 samples per interval, g = 9.81744, initial
#       bias 32768, verbose output off) on the recording given as its last argument.
#   ALLANTOOLS_CMD  (--allantools)  called as `CMD FILE RATE_HZ AXES` (AXES "1" or "1,2,3",
#       columns after t): loads FILE with numpy.loadtxt and runs allantools.oadev (frequency
#       data) per axis at accelcal's averaging factors (every octave plus 10 per decade, up to N/4).
# The accelcal binary is --accelcal (default build-release/accelcal, a Release build).
#
# Rows (peer / accelcal = how many times faster accelcal is; the goal is >= 10):
#   fit     accelcal fit --recording XSENS --gravity 9.81744   vs  IMU_TK_ACC_CMD XSENS
#           (the imu_tk Xsens file, tests/data/imu_tk/xsens_acc.mat by default)
#   fit --no-diagnose  the same with the nine parameters only (imu_tk's work: no model search)
#   allan   accelcal allan REC (three axes)                     vs  ALLANTOOLS_CMD REC R 1,2,3
#   allan/axis  accelcal's three-axis figure / 3                vs  ALLANTOOLS_CMD REC R 1
#   reading: MB/s of the first --read-hours of REC through `cat`, `wc -l`, `accelcal record
#           --source file:` (to /dev/null), `accelcal allan` and `accelcal fit --recording` (a still
#           record has no poses: fit reads, parses and detects, then fails as expected); and the
#           reader alone, `ReadRecording` of that file in the benchmark BM_ReadRecordingLarge of
#           --accelcal-bench (default build-release/bench/accelcal_bench; skipped without it),
#           in MB/s of its CPU time (10^6 bytes; the benchmark's own M/s is MiB/s): goal >= 500.
# REC is a still recording of --hours H (default 12) at --rate-hz R (default 1000), generated once
# into --workdir with `accelcal record --source sim --speed 0` from scenarios/drift_demo.toml at
# rate R and reused (12 h at 1 kHz: 43.2 M lines, 1.2 GB, 1-2 min to generate; allantools then
# needs ~2 GB and a few minutes a run). Give `--hours 1` on a busy machine: ratios are what matter.
#
# Timing: GNU time (/usr/bin/time) of each process; the commands of a row run interleaved
# (A B A B ...), after one warm-up of each for the small rows, --runs times (default 7; the Allan
# rows --allan-runs, default 3). Small commands run --reps times (default 10) inside one timed
# loop, to get past time's 10 ms resolution; figures are per run. Printed: medians of CPU
# (user + sys) and wall seconds, the largest max RSS, and the ratio as the median of the per-pair
# ratios (robust to a machine whose speed drifts); the goal is judged on CPU. The machine's load
# is printed before and after: on a shared machine quote ratios, not absolute times.
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
accelcal=$repo/build-release/accelcal
accelcal_bench=$repo/build-release/bench/accelcal_bench
imu_tk_cmd=${IMU_TK_ACC_CMD:-}
allantools_cmd=${ALLANTOOLS_CMD:-}
hours=12 rate=1000 read_hours=1 runs=7 allan_runs=3 reps=10
xsens=$repo/tests/data/imu_tk/xsens_acc.mat
workdir=${TMPDIR:-/tmp}/accelcal-bench-peers

die() { echo "bench_peers: $*" >&2; exit 2; }
opts=" --accelcal --peers --imu-tk-acc --allantools --hours --rate-hz --read-hours --runs --allan-runs"
opts+=" --reps --xsens --workdir --accelcal-bench "
while (($#)); do
  if [[ $1 == -h || $1 == --help ]]; then
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
    exit 0
  fi
  [[ $opts == *" $1 "* ]] || die "unknown option $1 (--help)"
  (($# >= 2)) || die "$1 needs a value (--help)"
  case $1 in
    --accelcal) accelcal=$2 ;;
    --accelcal-bench) accelcal_bench=$2 ;;
    --peers)
      [[ -x $2/imu_tk/imu_tk_acc ]] && imu_tk_cmd=$2/imu_tk/imu_tk_acc
      [[ -f $2/allantools/oadev_axes.py ]] && allantools_cmd="/usr/bin/python3 $2/allantools/oadev_axes.py"
      [[ -n $imu_tk_cmd || -n $allantools_cmd ]] || die "no peers built in $2 (scripts/bench_peers_build.sh)" ;;
    --imu-tk-acc) imu_tk_cmd=$2 ;;
    --allantools) allantools_cmd=$2 ;;
    --hours) hours=$2 ;;
    --rate-hz) rate=$2 ;;
    --read-hours) read_hours=$2 ;;
    --runs) runs=$2 ;;
    --allan-runs) allan_runs=$2 ;;
    --reps) reps=$2 ;;
    --xsens) xsens=$2 ;;
    --workdir) workdir=$2 ;;
  esac
  shift 2
done
for n in "$runs" "$allan_runs" "$reps"; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || die "runs and reps are positive integers, not '$n'"
done
for x in "$hours" "$rate" "$read_hours"; do
  [[ $x =~ ^[0-9]*\.?[0-9]+$ && $x =~ [1-9] ]] || die "hours and rates are positive numbers, not '$x'"
done
[[ -x $accelcal ]] ||
  die "no accelcal binary at $accelcal (BUILD_DIR=build-release BUILD_TYPE=Release scripts/build.sh)"
[[ -x /usr/bin/time ]] || die "/usr/bin/time is missing (Debian: apt-get install time)"
[[ -r $xsens ]] || die "no Xsens recording at $xsens (--xsens FILE)"
mkdir -p "$workdir"
log=$workdir/runs && rm -rf "$log" && mkdir -p "$log"
accelcal=$(realpath "$accelcal")

machine() {
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)," \
    "load average $(cut -d' ' -f1-3 /proc/loadavg)"
}

# measure KEY REPS ALLOW_FAIL(0|1) -- CMD...: one timed run of CMD (REPS times in one loop),
# appends "cpu wall maxrss_kb" per rep to $log/KEY.
measure() {
  local key=$1 n=$2 allow=$3; shift 4
  local tf=$log/$key.time
  # shellcheck disable=SC2016  # the loop's $1, $2, $@ are the inner bash's
  if ! /usr/bin/time -f '%U %S %e %M' -o "$tf" bash -c \
      'n=$1 allow=$2; shift 2
       for ((i = 0; i < n; i++)); do "$@" >/dev/null 2>&1 || [[ $allow == 1 ]] || exit 1; done' \
      _ "$n" "$allow" "$@"; then
    echo "bench_peers: failed: $* (run it by hand to see why)" >&2; exit 1
  fi
  awk -v n="$n" '{ printf "%.6f %.6f %d\n", ($1 + $2) / n, $3 / n, $4 }' "$tf" >>"$log/$key"
}
# col KEY FIELD: the values of FIELD (1 cpu, 2 wall, 3 rss) of KEY's runs, one a line.
col() { awk -v f="$2" '{ print $f }' "$log/$1"; }
median() {
  sort -g | awk '{ v[NR] = $1 }
    END { if (NR == 0) exit 1; print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
med() { col "$1" "$2" | median; }
maxrss_mb() { col "$1" 3 | sort -g | tail -1 | awk '{ printf "%.0f", $1 / 1024 }'; }
# pair_ratio A B FIELD [DIV]: median over runs of B/(A/DIV).
pair_ratio() {
  paste <(col "$1" "$3") <(col "$2" "$3") | awk -v d="${4:-1}" '{ print $2 / ($1 / d) }' | median
}

row() {  # row WORK A_KEY B_KEY [DIV]: one line of the comparison table
  local d=${4:-1}
  printf '%-34s %9.3f %9.3f %7s | %9.3f %9.3f %7s | %6.1fx %6.1fx  %s\n' "$1" \
    "$(awk -v v="$(med "$2" 1)" -v d="$d" 'BEGIN { print v / d }')" \
    "$(awk -v v="$(med "$2" 2)" -v d="$d" 'BEGIN { print v / d }')" "$(maxrss_mb "$2")" \
    "$(med "$3" 1)" "$(med "$3" 2)" "$(maxrss_mb "$3")" \
    "$(pair_ratio "$2" "$3" 1 "$d")" "$(pair_ratio "$2" "$3" 2 "$d")" \
    "$(awk -v r="$(pair_ratio "$2" "$3" 1 "$d")" 'BEGIN { print (r >= 10) ? "met" : "not met" }')"
}

echo "accelcal: $accelcal"
machine
imu_tk=() allantools=()
if [[ -n $imu_tk_cmd ]]; then read -ra imu_tk <<<"$imu_tk_cmd"
else echo "imu_tk: not given (IMU_TK_ACC_CMD or --imu-tk-acc): the fit rows are skipped"; fi
if [[ -n $allantools_cmd ]]; then read -ra allantools <<<"$allantools_cmd"
else echo "allantools: not given (ALLANTOOLS_CMD or --allantools): the allan rows are skipped"; fi

# Inputs: the still recording (generated once, reused) and its first --read-hours.
rec=$workdir/still_${hours}h_${rate}hz.txt
if [[ ! -s $rec ]]; then
  sed "s/^rate_hz = [0-9.]*/rate_hz = $rate/" "$repo/scenarios/drift_demo.toml" >"$workdir/still_${rate}hz.toml"
  echo "generating $rec ($hours h at $rate Hz) ..."
  "$accelcal" record --source sim --speed 0 --scenario "$workdir/still_${rate}hz.toml" \
    --duration "$(awk -v h="$hours" 'BEGIN { print h * 3600 }')" -q -o "$rec.part"
  mv "$rec.part" "$rec"
fi
read_file=$workdir/still_${read_hours}h_of_${hours}h_${rate}hz.txt
lines=$(awk -v h="$read_hours" -v r="$rate" 'BEGIN { printf "%d", h * 3600 * r + 2 }')  # + 2 comments
[[ -s $read_file ]] || head -n "$lines" "$rec" >"$read_file"
cat "$rec" "$read_file" "$xsens" >/dev/null  # into the page cache
echo "recording: $rec ($(wc -l <"$rec") lines, $(stat -c %s "$rec" | awk '{ printf "%.0f", $1 / 1e6 }') MB)"

fit_cmd=("$accelcal" fit --recording "$xsens" --gravity 9.81744)
fit_nd_cmd=("$accelcal" fit --no-diagnose --recording "$xsens" --gravity 9.81744)
if ((${#imu_tk[@]})); then
  echo "fit: $runs runs x $reps reps each ..."
  measure w_a "$reps" 0 -- "${fit_cmd[@]}" && measure w_b "$reps" 0 -- "${imu_tk[@]}" "$xsens"
  measure w_n "$reps" 0 -- "${fit_nd_cmd[@]}" && rm -f "$log"/w_*
  for ((r = 0; r < runs; r++)); do
    measure fit_a "$reps" 0 -- "${fit_cmd[@]}"
    measure fit_b "$reps" 0 -- "${imu_tk[@]}" "$xsens"
    measure fit_n "$reps" 0 -- "${fit_nd_cmd[@]}"
  done
fi
if ((${#allantools[@]})); then
  echo "allan: $allan_runs runs (each allantools run can take minutes on 12 h) ..."
  for ((r = 0; r < allan_runs; r++)); do
    measure allan_a 1 0 -- "$accelcal" allan "$rec"
    measure allan_b 1 0 -- "${allantools[@]}" "$rec" "$rate" 1,2,3
    measure allan_b1 1 0 -- "${allantools[@]}" "$rec" "$rate" 1
  done
fi
echo "reading: $runs runs ..."
for ((r = 0; r < runs; r++)); do
  measure rd_cat "$reps" 0 -- cat "$read_file"
  measure rd_wc "$reps" 0 -- wc -l "$read_file"
  measure rd_record 1 0 -- "$accelcal" record --source "file:$read_file" -q -o /dev/null
  measure rd_allan 1 0 -- "$accelcal" allan "$read_file"
  measure rd_fit 1 1 -- "$accelcal" fit --recording "$read_file"
  if [[ -x $accelcal_bench ]]; then  # the reader alone: CPU ms of one ReadRecording, csv column 4
    ACCELCAL_BENCH_RECORDING=$read_file "$accelcal_bench" --benchmark_filter='^BM_ReadRecordingLarge' \
      --benchmark_format=csv 2>/dev/null |
      awk -F, '/BM_ReadRecordingLarge/ && $5 == "ms" { print $4 / 1000, $3 / 1000, 0 }' >>"$log/rd_reader"
  fi
done

echo
machine
printf '\n%-34s %29s | %29s | %15s\n' "" "accelcal" "peer" "peer / accelcal"
printf '%-34s %9s %9s %7s | %9s %9s %7s | %7s %7s  %s\n' work "cpu s" "wall s" "RSS MB" "cpu s" "wall s" "RSS MB" cpu wall "goal >= 10x"
if ((${#imu_tk[@]})); then
  row "fit --recording Xsens vs imu_tk" fit_a fit_b
  row "fit --no-diagnose vs imu_tk" fit_n fit_b
fi
if ((${#allantools[@]})); then
  row "allan ${hours}h ${rate}Hz, 3 axes" allan_a allan_b
  row "allan per axis (accelcal 3ax / 3)" allan_a allan_b1 3
fi
mb=$(stat -c %s "$read_file" | awk '{ printf "%.1f", $1 / 1e6 }')
printf '\nreading %s MB (%s h of the recording)   MB/s by cpu   MB/s by wall   max RSS MB\n' "$mb" "$read_hours"
declare -A label=([cat]="cat" [wc]="wc -l" [record]="accelcal record --source file:"
  [allan]="accelcal allan (3 axes)" [fit]="accelcal fit --recording (no poses)")
for k in cat wc record allan fit; do
  cpu=$(med "rd_$k" 1) wall=$(med "rd_$k" 2)
  printf '  %-36s %12.0f %14.0f %12s\n' "${label[$k]}" "$(awk -v m="$mb" -v t="$cpu" 'BEGIN { print (t > 0) ? m / t : "inf" }')" \
    "$(awk -v m="$mb" -v t="$wall" 'BEGIN { print (t > 0) ? m / t : "inf" }')" "$(maxrss_mb "rd_$k")"
done
if [[ -s $log/rd_reader ]]; then
  cpu=$(med rd_reader 1) wall=$(med rd_reader 2)
  reader_mbps=$(awk -v m="$mb" -v t="$cpu" 'BEGIN { printf "%.0f", m / t }')
  printf '  %-36s %12s %14.0f %12s  goal >= 500 MB/s: %s\n' "reader alone (BM_ReadRecordingLarge)" \
    "$reader_mbps" "$(awk -v m="$mb" -v t="$wall" 'BEGIN { print m / t }')" "-" \
    "$( ((reader_mbps >= 500)) && echo met || echo "not met")"
else
  echo "  reader alone: no benchmark binary at $accelcal_bench (--accelcal-bench PATH): skipped"
fi
echo "(record's figure includes writing the recording to /dev/null; per-run figures: $log)"

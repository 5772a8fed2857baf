#!/usr/bin/env bash
# End to end: `accelcal noise --record` reads a long record in passes, block by block, so its
# memory does not grow with the record: a 200 s record at 10 kHz (2 M lines, 46 MB of text, 80 MB
# as samples) analysed from the file and, held in memory, from a pipe; the two reports the same,
# the file's peak resident set well under the pipe's. Called by ctest as:
#   noise_memory.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
: "$data"
source "$src/tests/e2e/lib/common.bash"
command -v python3 >/dev/null || { echo "python3 missing: skipped"; exit 77; }

# White noise of 2 counts, rounded, a slow drift on y; t at 10 kHz with a jitter of 1 us (so
# the median interval goes by digits, replay_selection.h).
python3 - "$work/long.txt" <<'PY'
import random, sys
random.seed(9)
with open(sys.argv[1], "w") as f:
    f.write("# t ax ay az\n")
    g = random.gauss
    for i in range(2_000_000):
        f.write("%.7f %d %d %d\n" % (i * 1e-4 + random.uniform(-1e-6, 1e-6),
                                     round(2048 + g(0, 2)), round(2040 + g(0, 2) + i * 1e-6),
                                     round(2400 + g(0, 2))))
PY

# Peak resident set (KiB) of a command run through bash, its stdout to $work/out.
peak_kib() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys
with open(sys.argv[1], "w") as out:
    rc = subprocess.call(["bash", "-c", sys.argv[2]], stdout=out)
if rc != 0:
    sys.exit(rc)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
PY
}
streamed=$(peak_kib "$work/file.json" "'$accelcal' noise --record '$work/long.txt' --format json 2>/dev/null") ||
  fail "noise on the file failed"
held=$(peak_kib "$work/pipe.json" "'$accelcal' noise --record <(cat '$work/long.txt') --format json 2>/dev/null") ||
  fail "noise on the pipe failed"
echo "peak resident set: file $streamed KiB, pipe (held) $held KiB"

# The same report but for the label (the path).
diff <(sed "s|$work/long.txt|RECORD|" "$work/file.json") <(sed "s|/dev/fd/[0-9]*|RECORD|" "$work/pipe.json") ||
  fail "the file's report differs from the pipe's"
[ "$(jq '.records[0].n_samples' "$work/file.json")" = 2000000 ] || fail "samples: $(jq '.records[0].n_samples' "$work/file.json")"
near() { awk -v v="$1" -v t="$2" -v e="$3" 'BEGIN { d = v - t; if (d < 0) d = -d; exit !(d <= e) }'; }
near "$(jq '.records[0].rate_hz' "$work/file.json")" 10000 1 || fail "rate $(jq '.records[0].rate_hz' "$work/file.json")"

# Memory: the samples alone would be 80 MB. Sanitizer builds keep freed memory in quarantine.
if ldd "$accelcal" 2>/dev/null | grep -q libasan; then
  echo "sanitizer build: resident set not compared"
else
  ((streamed < 48 * 1024)) || fail "the file took $streamed KiB (bounded: expected < 48 MiB)"
  ((streamed * 2 < held)) || fail "the file took $streamed KiB, the held pipe $held KiB"
fi
echo "noise_memory: ok"

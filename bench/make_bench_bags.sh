#!/usr/bin/env bash
# Writes the bags of bench/bag_reader_bench.cpp into DIR: a still record from the virtual bench
# (N samples at 100 Hz; default 2 900 000, 8 h: a 1 GB uncompressed bag), as imu.txt (the same
# samples as text, m/s^2) and as bags written by tests/e2e/lib/bags/write_bags.mjs (npm peers
# installed into DIR/peers). FORMS limits the bags (write_bags.mjs --forms; default all).
# Usage: bench/make_bench_bags.sh DIR [N [FORMS]]; then
#   ACCELCAL_BENCH_BAGS=DIR build-release/bench/accelcal_bench --benchmark_filter=Bag\|ImuText
set -euo pipefail
dir=$1
samples=${2:-2900000}
forms=${3:-all}
src=$(cd "$(dirname "$0")/.." && pwd)
accelcal=${ACCELCAL:-$src/build-release/accelcal}
mkdir -p "$dir"
bash "$src/tests/e2e/lib/bags/install.sh" "$dir/peers"
cp "$src/tests/e2e/lib/bags"/*.mjs "$dir/peers/"
"$accelcal" record --source sim --speed 0 --duration "$(awk -v n="$samples" 'BEGIN { print n / 100 }')" \
  -o "$dir/counts.txt" -q
node --max-old-space-size=8192 "$dir/peers/write_bags.mjs" "$dir/counts.txt" "$dir" --forms "$forms"
ls -l "$dir"

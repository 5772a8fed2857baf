#!/usr/bin/env bash
# End to end: damaged bags (written by code nobody here wrote, then damaged here).
#   - cut short (a recorder killed): every format read up to its last whole message, said in the
#     read line, and the samples read are the first ones of the text, exactly;
#   - a chunk whose CRC does not match (MCAP), corrupt zstd and bz2 chunks: refused naming the
#     chunk and its byte;
#   - a ROS 2 SQLite bag damaged part way: read up to its last readable row, said; one cut where
#     its tables are described: refused saying so;
#   - a bag folder whose files rosbag2 compressed whole, or whose metadata.yaml names a missing
#     file; a ROS bag of an older format: refused with what to do.
# Needs node and npm (the writers are installed once into the build folder); exit 77 without.
# Called by ctest as: bags_damaged.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
: "$data"
source "$src/tests/e2e/lib/common.bash"
peers=$(dirname "$accelcal")/bag-peers
bash "$src/tests/e2e/lib/bags/install.sh" "$peers" || exit $?
cp "$src/tests/e2e/lib/bags"/*.mjs "$peers/"

python3 "$src/tests/e2e/lib/field_gen.py" recording --poses near40 --seed 5 --rate 100 \
  --style plain -o "$work/rec.txt" --truth "$work/truth.json"
head -n 10000 "$work/rec.txt" > "$work/short.txt"
node "$peers/write_bags.mjs" "$work/short.txt" "$work/b" >/dev/null
b=$work/b
d=$work/damaged
mkdir -p "$d"

# The samples of `record FILE` (the bag's values) against the text's first lines, as numbers.
same_prefix() {  # same_prefix RECORDED TEXT
  local n
  n=$(grep -vc '^#' "$1")
  paste -d' ' <(grep -v '^#' "$1") <(head -n "$n" "$2") |
    awk '{ if ($1 != $5 || $2 != $6 || $3 != $7 || $4 != $8) { print "line " NR ": " $0; bad = 1; exit } } END { exit bad }'
}

for f in imu_zstd.mcap imu_lz4.mcap imu_none.mcap imu_none.bag imu_bz2.bag imu_lz4.bag; do
  size=$(stat -c %s "$b/$f")
  head -c $((size * 6 / 10)) "$b/$f" > "$d/cut_$f"
  expect 0 "$accelcal" allan "$d/cut_$f" -o "$d/cut_$f.json"
  grep -q "cut short at byte $((size * 6 / 10)) .*read up to its last whole message" "$work/out" ||
    { cat "$work/out"; fail "cut $f: not said"; }
  n=$(jq .samples "$d/cut_$f.json")
  [ "$n" -gt 1000 ] && [ "$n" -lt 10000 ] || fail "cut $f: $n samples"
  expect 0 "$accelcal" record --source "file:$d/cut_$f" -o "$d/cut_$f.txt" -q
  [ "$(grep -vc '^#' "$d/cut_$f.txt")" -eq "$n" ] || fail "cut $f: record and allan read different counts"
  same_prefix "$d/cut_$f.txt" "$b/imu.txt" || fail "cut $f: not the text's first $n samples"
done
expect 0 "$accelcal" bag-info "$d/cut_imu_bz2.bag"
grep -q "^note: its index is said to start at byte .* past its end" "$work/out" || fail "bag-info on a cut bag"

# One byte changed inside the first chunk.
flip() {  # flip IN OUT OFFSET: a copy with the byte at OFFSET changed
  cp "$1" "$2"
  local v
  v=$(od -An -tu1 -j "$3" -N1 "$2" | tr -d ' ')
  printf "$(printf '\\%03o' $(((v + 1) % 256)))" | dd of="$2" bs=1 seek="$3" conv=notrunc 2>/dev/null
}
flip "$b/imu_none.mcap" "$d/crc.mcap" 30000
expect 1 "$accelcal" allan "$d/crc.mcap"
grep -qE "crc.mcap: chunk 1 \(at byte [0-9]+\): its records' CRC-32 is [0-9a-f]{8}, the chunk states [0-9a-f]{8}: the file is damaged there" "$work/err" ||
  fail "a bad chunk CRC: $(cat "$work/err")"
flip "$b/imu_zstd.mcap" "$d/zstd.mcap" 3000
expect 1 "$accelcal" fit --recording "$d/zstd.mcap"
grep -qE "zstd.mcap: chunk 1 \(at byte [0-9]+\): .*: the file is damaged there" "$work/err" || fail "a corrupt zstd chunk: $(cat "$work/err")"
flip "$b/imu_bz2.bag" "$d/bz2.bag" 8000
expect 1 "$accelcal" allan "$d/bz2.bag"
grep -qE "bz2.bag: chunk 1 \(at byte [0-9]+\): bz2: the data is corrupt .*: the file is damaged there" "$work/err" ||
  fail "a corrupt bz2 chunk: $(cat "$work/err")"

# ROS 2 SQLite: pages zeroed part way (read up to there), and a file cut short.
cp "$b/imu.db3" "$d/zeroed.db3"
size=$(stat -c %s "$b/imu.db3")
dd if=/dev/zero of="$d/zeroed.db3" bs=4096 seek=$((size * 7 / 10 / 4096)) count=100 conv=notrunc 2>/dev/null
expect 0 "$accelcal" allan "$d/zeroed.db3" -o "$d/zeroed.json"
grep -q "the database is damaged after its [0-9]* readable messages (SQLite: .*): read up to there" "$work/out" ||
  fail "a damaged db3: $(cat "$work/out")"
n=$(jq .samples "$d/zeroed.json")
[ "$n" -gt 1000 ] && [ "$n" -lt 10000 ] || fail "zeroed db3: $n samples"
head -c $((size / 2)) "$b/imu.db3" > "$d/cut.db3"
expect 1 "$accelcal" allan "$d/cut.db3"
grep -q "cut.db3: its SQLite database cannot be read (SQLite: .*): damaged, or cut short where its tables are described" "$work/err" ||
  fail "a cut db3: $(cat "$work/err")"

# Bag folders rosbag2 compressed, or whose files are missing; an older ROS bag format.
cp -r "$b/imu_sqlite" "$d/compressed"
sed -i -e 's/^  compression_format: .*/  compression_format: zstd/' -e 's/^  compression_mode: .*/  compression_mode: FILE/' "$d/compressed/metadata.yaml"
expect 1 "$accelcal" allan "$d/compressed"
grep -q "rosbag2 compressed its files whole with zstd (compression_mode FILE): not read; decompress it first" "$work/err" ||
  fail "a compressed bag folder: $(cat "$work/err")"
cp -r "$b/imu_mcapdir" "$d/missing"
rm "$d"/missing/*.mcap
expect 1 "$accelcal" fit --recording "$d/missing"
grep -q "its file 'imu_mcapdir_0.mcap' (metadata.yaml) is not there" "$work/err" || fail "a missing file: $(cat "$work/err")"
printf '#ROSRECORD V1.2\n' > "$d/old.bag"
head -c 5000 /dev/zero >> "$d/old.bag"
expect 1 "$accelcal" allan "$d/old.bag"
grep -q "a ROS bag of format '#ROSRECORD V1.2': only format 2.0 is read" "$work/err" || fail "an old bag: $(cat "$work/err")"
echo "bags_damaged: cut files read up to their last whole message; damage refused naming where"

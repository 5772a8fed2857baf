#!/usr/bin/env bash
# End to end: the same IMU data as text, as ROS 1 bags (chunks uncompressed, bz2, lz4), as ROS 2
# SQLite bags (a .db3, and a bag folder with metadata.yaml) and as MCAP (zstd, lz4 and
# uncompressed chunks; and in a bag folder) give the same calibration, Allan figures, noise
# figures and calibrated samples, bit for bit. The bags are written by code nobody here wrote
# (tests/e2e/lib/bags/write_bags.mjs: @mcap/core, the foxglove serializers, sql.js's SQLite;
# the ROS 1 bags laid out from the format's description and read back by @foxglove/rosbag).
# Then the refusals, each with what the bag holds: a topic that is not there, a topic of another
# type, two IMU topics and no --topic, a schema that is not Imu's, a unit other than m/s^2,
# stamps that go back (the text reader's words), zero stamps (the receive times, said), the
# file: source and `record` replaying a bag, and bag-info.
# Needs node and npm (the peers are installed once into the build folder); exit 77 without.
# Called by ctest as: bags_formats.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$1 src=$2 data=$3
: "$data"
source "$src/tests/e2e/lib/common.bash"
peers=$(dirname "$accelcal")/bag-peers
bash "$src/tests/e2e/lib/bags/install.sh" "$peers" || exit $?
lib="$src/tests/e2e/lib/bags"
# ES modules resolve packages from their own folder: the scripts run from a copy beside the peers.
cp "$lib"/*.mjs "$peers/"

# The recording: 40 hand-placed poses after a still start, 100 Hz, from the independent
# generator; the bags hold it in m/s^2 (write_bags.mjs converts it as a driver would).
python3 "$src/tests/e2e/lib/field_gen.py" recording --poses near40 --seed 11 --rate 100 \
  --style plain -o "$work/rec.txt" --truth "$work/truth.json"
node "$peers/write_bags.mjs" "$work/rec.txt" "$work/b" >/dev/null
b=$work/b
forms=(imu_none.bag imu_bz2.bag imu_lz4.bag imu.db3 imu_sqlite imu_zstd.mcap imu_lz4.mcap
       imu_none.mcap imu_mcapdir)

# The hand-built ROS 1 bags, read by @foxglove/rosbag: the same samples as the text.
for c in none bz2 lz4; do
  node "$peers/read_ros1.mjs" "$b/imu_$c.bag" /imu/data >"$work/ros1_$c.txt" 2>"$work/ros1_$c.err" ||
    { cat "$work/ros1_$c.err" >&2; fail "@foxglove/rosbag cannot read imu_$c.bag"; }
  cmp -s "$work/ros1_$c.txt" "$b/imu.txt" || fail "@foxglove/rosbag reads other samples from imu_$c.bag"
  grep -q "^/status std_msgs/String 372$" "$work/ros1_$c.err" || fail "imu_$c.bag: /status count"
done

# fit --recording: the text (declared m/s^2) and every bag, the same nine parameters.
figures() { jq -c '[.bias_counts, .scale_counts_per_mps2, .misalignment_rad, .uncertainty,
                    .residual_rms_mps2, .residual_max_abs_mps2, .reading_unit]' "$1"; }
expect 0 "$accelcal" fit --recording "$b/imu.txt" --unit m/s^2 -o "$work/text.cal.json"
grep -q "40 captures" "$work/out" || fail "the text's fit did not find the 40 poses"
want=$(figures "$work/text.cal.json")
for f in "${forms[@]}"; do
  expect 0 "$accelcal" fit --recording "$b/$f" -o "$work/$f.cal.json"
  grep -q "^read $b/$f: 37200 samples; topic /imu/data" "$work/out" || { cat "$work/out"; fail "$f: read line"; }
  [ "$(figures "$work/$f.cal.json")" = "$want" ] || fail "$f: another calibration than the text's"
done

# allan: the same figures and curves.
expect 0 "$accelcal" allan "$b/imu.txt" --unit m/s^2 -o "$work/text.allan.json"
want=$(jq -c '[.unit, .rate_hz, .samples, .gaps, .axes]' "$work/text.allan.json")
for f in "${forms[@]}"; do
  expect 0 "$accelcal" allan "$b/$f" -o "$work/$f.allan.json"
  [ "$(jq -c '[.unit, .rate_hz, .samples, .gaps, .axes]' "$work/$f.allan.json")" = "$want" ] ||
    fail "$f: other Allan figures than the text's"
done

# noise (with the calibration, as text files need it) and apply: the same figures and lines.
cal=$work/text.cal.json
expect 0 "$accelcal" noise --record "$b/imu.txt" --calibration "$cal" --format json -o "$work/text.noise.json"
want=$(jq -c '[.records[0].axes, .unit]' "$work/text.noise.json")
expect 0 "$accelcal" apply "$cal" "$b/imu.txt" --unit m/s^2
cp "$work/out" "$work/text.applied"
for f in imu_bz2.bag imu.db3 imu_zstd.mcap imu_mcapdir; do
  expect 0 "$accelcal" noise --record "$b/$f" --calibration "$cal" --format json -o "$work/$f.noise.json"
  [ "$(jq -c '[.records[0].axes, .unit]' "$work/$f.noise.json")" = "$want" ] || fail "$f: other noise figures"
  expect 0 "$accelcal" apply "$cal" "$b/$f"
  cmp -s "$work/out" "$work/text.applied" || fail "$f: apply writes other lines than for the text"
  grep -q "accelcal: read .*37200 samples; topic /imu/data" "$work/err" || fail "$f: apply's read line"
done
[ "$(wc -l < "$work/text.applied")" -eq 37200 ] || fail "apply wrote $(wc -l < "$work/text.applied") lines"
# Without a calibration a bag's noise is in m/s^2 as recorded, and says so.
expect 0 "$accelcal" noise --record "$b/imu_lz4.mcap" --format json -o "$work/raw.noise.json"
[ "$(jq -r .unit "$work/raw.noise.json")" = "m/s^2" ] || fail "a bag's noise without a calibration"
expect 1 "$accelcal" noise --record "$b/imu_lz4.mcap" "$b/imu.txt"
grep -q "is a bag (m/s^2) and .* is not" "$work/err" || fail "bags and text mixed: $(cat "$work/err")"

# The file: source, and record replaying a bag: the bag's values, read back as the same data.
expect 0 "$accelcal" record --source "file:$b/imu_lz4.bag" -o "$work/replayed.txt" -q
grep -q "^# readings in m/s^2" "$work/replayed.txt" || fail "record does not say the unit"
expect 0 "$accelcal" fit --recording "$work/replayed.txt" --unit m/s^2 -o "$work/replayed.cal.json"
[ "$(figures "$work/replayed.cal.json")" = "$(figures "$cal")" ] || fail "a replayed bag calibrates otherwise"

# bag-info: the topics with their types, counts and rates; the IMU topic's stamps.
expect 0 "$accelcal" bag-info "$b/imu_sqlite"
grep -qE "^  /imu/data +sensor_msgs/msg/Imu +37200 +99.9" "$work/out" || { cat "$work/out"; fail "bag-info: /imu/data"; }
grep -qE "^  /status +std_msgs/msg/String +372 " "$work/out" || fail "bag-info: /status"
grep -q "/imu/data: 37200 stamps, 100 Hz, no gap, none out of order" "$work/out" || fail "bag-info: stamps"

# Refusals, each saying what the bag holds.
expect 1 "$accelcal" fit --recording "$b/imu_zstd.mcap" --topic /imu
grep -q "0 messages on topic /imu: the topics are /imu/data (sensor_msgs/msg/Imu, 37200 messages, 100 Hz), /status (std_msgs/msg/String, 372 messages" "$work/err" ||
  fail "an absent topic: $(cat "$work/err")"
expect 1 "$accelcal" allan "$b/imu_bz2.bag" --topic /status
grep -q "topic /status holds std_msgs/String messages, not sensor_msgs/Imu; its IMU topic: /imu/data (sensor_msgs/Imu, 37200 messages" "$work/err" ||
  fail "a topic of another type: $(cat "$work/err")"
expect 1 "$accelcal" fit --recording "$b/imu.db3" --unit counts
grep -q "linear_acceleration is in m/s^2, and the readings were declared in counts" "$work/err" || fail "--unit counts on a bag"
expect 1 "$accelcal" fit --recording "$b/imu.txt" --topic /imu/data
grep -q "is not a bag" "$work/err" || fail "--topic on a text"

# Variants on the first 3000 samples: two IMU topics, stamps out of order, zero stamps, a wrong schema.
head -n 3000 "$work/rec.txt" > "$work/short.txt"
for v in two_imu swapped zero_stamps wrong_schema; do
  node "$peers/write_bags.mjs" "$work/short.txt" "$work/$v" --variant "$v" >/dev/null
done
expect 1 "$accelcal" allan "$work/two_imu/imu_zstd.mcap"
grep -q "holds 2 IMU topics: /imu/data (sensor_msgs/msg/Imu, 3000 messages, 100 Hz), /imu/raw (sensor_msgs/msg/Imu, 3000 messages, 100 Hz): give the one to read with --topic NAME" "$work/err" ||
  fail "two IMU topics: $(cat "$work/err")"
expect 0 "$accelcal" allan "$work/two_imu/imu.db3" --topic /imu/raw
grep -q "3000 samples; topic /imu/raw" "$work/out" || fail "--topic /imu/raw"

expect 1 "$accelcal" allan "$work/swapped/imu.txt" --unit m/s^2
text_words=$(sed -E 's/^.*: (t = .*)$/\1/' "$work/err")
[ -n "$text_words" ] || fail "the text's order error"
for f in imu_zstd.mcap imu.db3 imu_none.bag; do
  expect 1 "$accelcal" allan "$work/swapped/$f"
  grep -qF "/imu/data message 1002: t = " "$work/err" || fail "$f: out of order: $(cat "$work/err")"
  bag_words=$(sed -E 's/^.*message 1002: (t = .*strictly increasing).*$/\1/' "$work/err")
  [ "$bag_words" = "$(sed 's/line 1001/message 1001/' <<<"$text_words")" ] ||
    fail "$f: other words than the text's: '$bag_words' vs '$text_words'"
  grep -q -- "--bag-time receive reads the bag's receive times" "$work/err" || fail "$f: no hint of --bag-time"
  expect 0 "$accelcal" allan "$work/swapped/$f" --bag-time receive
  grep -q "t from the bag's receive times (--bag-time receive)" "$work/out" || fail "$f: --bag-time receive"
done

expect 0 "$accelcal" allan "$work/zero_stamps/imu_lz4.bag"
grep -q "t from the bag's receive times (the messages' header stamps are zero)" "$work/out" || fail "zero stamps"

expect 1 "$accelcal" allan "$work/wrong_schema/imu_zstd.mcap"
grep -q "topic /imu/data says sensor_msgs/msg/Imu but its schema is not that message's: its Header (ROS 2's: stamp, frame_id) has 'uint32 seq' where 'Time stamp' belongs" "$work/err" ||
  fail "a wrong schema: $(cat "$work/err")"
echo "bags_formats: ${#forms[@]} bag forms agree with the text; refusals clear"

// The bag readers' parts on bytes laid out here from the formats' descriptions (CDR, ROS 1
// serialization, MCAP records, rosbag2's metadata.yaml), independent of the readers' code. The
// formats are proven against writers written elsewhere in tests/e2e/bags_formats.sh.
#include <lz4frame.h>
#include <unistd.h>
#include <zstd.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/bags/bag_sample_stream.h"
#include "accelcal/bags/chunk_codec.h"
#include "accelcal/bags/crc32.h"
#include "accelcal/bags/imu_message.h"
#include "accelcal/bags/ros2_bag_folder.h"
#include "accelcal/base/error.h"
#include "accelcal/base/sample_time_check.h"
#include "test_support.h"

namespace accelcal::bags {
namespace {

using accelcal::testing::Contains;

// --- little writers of the formats, from their descriptions ------------------------------------
void PutLittle(std::vector<uint8_t>* out, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out->push_back(static_cast<uint8_t>(v >> (8 * i)));
}
void PutBig(std::vector<uint8_t>* out, uint64_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) out->push_back(static_cast<uint8_t>(v >> (8 * i)));
}
void PutDouble(std::vector<uint8_t>* out, double d, bool big) {
  uint64_t bits;
  std::memcpy(&bits, &d, 8);
  big ? PutBig(out, bits, 8) : PutLittle(out, bits, 8);
}

// sensor_msgs/msg/Imu in CDR: encapsulation, stamp, frame_id (with its NUL), padding to 8 from
// the body's start, then 37 float64 with linear_acceleration the 26th to 28th.
std::vector<uint8_t> CdrImu(int32_t sec, uint32_t nsec, const std::string& frame, double ax,
                            double ay, double az, bool big) {
  std::vector<uint8_t> m = {0, static_cast<uint8_t>(big ? 0 : 1), 0, 0};
  const auto put = [&](uint64_t v, int n) { big ? PutBig(&m, v, n) : PutLittle(&m, v, n); };
  put(static_cast<uint32_t>(sec), 4);
  put(nsec, 4);
  put(frame.size() + 1, 4);
  for (char c : frame) m.push_back(static_cast<uint8_t>(c));
  m.push_back(0);
  while ((m.size() - 4) % 8 != 0) m.push_back(0);
  for (int i = 0; i < 37; ++i) {
    double v = 0.5 + i;
    if (i == 25) v = ax;
    if (i == 26) v = ay;
    if (i == 27) v = az;
    PutDouble(&m, v, big);
  }
  return m;
}

// sensor_msgs/Imu in ROS 1: seq, stamp, frame_id without NUL, 37 float64, packed.
std::vector<uint8_t> Ros1Imu(uint32_t sec, uint32_t nsec, const std::string& frame, double ax,
                             double ay, double az) {
  std::vector<uint8_t> m;
  PutLittle(&m, 7, 4);
  PutLittle(&m, sec, 4);
  PutLittle(&m, nsec, 4);
  PutLittle(&m, frame.size(), 4);
  for (char c : frame) m.push_back(static_cast<uint8_t>(c));
  for (int i = 0; i < 37; ++i) PutDouble(&m, i == 25 ? ax : i == 26 ? ay : i == 27 ? az : 1.0, false);
  return m;
}

TEST(BagCrc32, TheCheckValueOfTheZlibCrc) {
  const std::string text = "123456789";
  EXPECT_EQ(Crc32(reinterpret_cast<const uint8_t*>(text.data()), text.size()), 0xCBF43926u);
  // In pieces, continued, the same; and over more than one 16-byte step.
  const std::string long_text(1000, 'x');
  const auto* p = reinterpret_cast<const uint8_t*>(long_text.data());
  EXPECT_EQ(Crc32(p + 333, 667, Crc32(p, 333)), Crc32(p, 1000));
}

TEST(BagImu, CdrLittleAndBigEndian) {
  for (bool big : {false, true}) {
    for (const std::string& frame : {std::string(), std::string("imu"), std::string("imu_link_0")}) {
      const std::vector<uint8_t> m = CdrImu(1700000000, 123456789, frame, 0.25, -9.80665, 1e-3, big);
      ImuReading r;
      std::string why;
      ASSERT_TRUE(DecodeImu(ImuEncoding::kCdr, m.data(), m.size(), &r, &why)) << why;
      EXPECT_EQ(r.stamp_sec, 1700000000);
      EXPECT_EQ(r.stamp_nsec, 123456789u);
      EXPECT_EQ(r.linear_acceleration[0], 0.25);
      EXPECT_EQ(r.linear_acceleration[1], -9.80665);
      EXPECT_EQ(r.linear_acceleration[2], 1e-3);
    }
  }
}

TEST(BagImu, CdrRefusals) {
  std::vector<uint8_t> m = CdrImu(1, 2, "imu", 1, 2, 3, false);
  ImuReading r;
  std::string why;
  std::vector<uint8_t> short_one(m.begin(), m.end() - 8);
  EXPECT_FALSE(DecodeImu(ImuEncoding::kCdr, short_one.data(), short_one.size(), &r, &why));
  EXPECT_TRUE(Contains(why, "where a sensor_msgs/msg/Imu with this frame_id has")) << why;
  std::vector<uint8_t> xcdr2 = m;
  xcdr2[1] = 0x07;
  EXPECT_FALSE(DecodeImu(ImuEncoding::kCdr, xcdr2.data(), xcdr2.size(), &r, &why));
  EXPECT_TRUE(Contains(why, "only CDR (XCDR1")) << why;
  const std::vector<uint8_t> nan = CdrImu(1, 2, "imu", 1, std::nan(""), 3, false);
  EXPECT_FALSE(DecodeImu(ImuEncoding::kCdr, nan.data(), nan.size(), &r, &why));
  EXPECT_TRUE(Contains(why, "linear_acceleration.y is nan, not a finite number")) << why;
}

TEST(BagImu, Ros1) {
  const std::vector<uint8_t> m = Ros1Imu(1500000000, 999999999, "base", -1.5, 0.0, 9.81);
  ImuReading r;
  std::string why;
  ASSERT_TRUE(DecodeImu(ImuEncoding::kRos1, m.data(), m.size(), &r, &why)) << why;
  EXPECT_EQ(r.stamp_sec, 1500000000);
  EXPECT_EQ(r.stamp_nsec, 999999999u);
  EXPECT_EQ(r.linear_acceleration[0], -1.5);
  EXPECT_EQ(r.linear_acceleration[2], 9.81);
  // A CDR message read as ROS 1 (or the reverse) has the wrong size: refused, not misread.
  const std::vector<uint8_t> cdr = CdrImu(1, 2, "base", 1, 2, 3, false);
  EXPECT_FALSE(DecodeImu(ImuEncoding::kRos1, cdr.data(), cdr.size(), &r, &why));
}

TEST(BagImu, SchemaChecks) {
  BagConnection c;
  c.type = "sensor_msgs/msg/Imu";
  c.encoding = "cdr";
  c.schema_encoding = "ros2msg";
  const std::string top =
      "# comment\nstd_msgs/Header header # the stamp\ngeometry_msgs/Quaternion orientation\n"
      "float64[9] orientation_covariance\ngeometry_msgs/Vector3 angular_velocity\n"
      "float64[9] angular_velocity_covariance\ngeometry_msgs/Vector3 linear_acceleration\n"
      "float64[9] linear_acceleration_covariance\n";
  const std::string sep = "================================================================================\n";
  c.schema = top + sep + "MSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id\n" + sep +
             "MSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n" + sep +
             "MSG: geometry_msgs/Quaternion\nfloat64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n";
  EXPECT_EQ(ImuSchemaMismatch(c, ImuEncoding::kCdr), "");
  // ROS 1's Header (with seq) in a CDR channel: its stamp would be read from the wrong bytes.
  BagConnection wrong = c;
  wrong.schema = top + sep + "MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n";
  EXPECT_EQ(ImuSchemaMismatch(wrong, ImuEncoding::kCdr),
            "its Header (ROS 2's: stamp, frame_id) has 'uint32 seq' where 'Time stamp' belongs");
  EXPECT_EQ(ImuSchemaMismatch(wrong, ImuEncoding::kRos1), "");
  BagConnection other = c;
  other.schema = "float32 x\nfloat32 y\n";
  EXPECT_TRUE(Contains(ImuSchemaMismatch(other, ImuEncoding::kCdr), "the definition has 'float32 x'"));
  BagConnection md5 = c;
  md5.encoding = "ros1";
  md5.schema.clear();
  md5.md5sum = "0123456789abcdef0123456789abcdef";
  EXPECT_TRUE(Contains(ImuSchemaMismatch(md5, ImuEncoding::kRos1), "not sensor_msgs/Imu's 6a62c6daae103f4ff57a132d6f95cec2"));
}

TEST(BagCodec, WholeAndCutFrames) {
  // About 500 kB of numbers that compress but not to nothing: several blocks of either codec.
  std::string data;
  uint64_t x = 88172645463325252ull;
  for (int i = 0; i < 40000; ++i) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    data += "sample " + std::to_string(x % 100000) + ";";
  }
  std::vector<uint8_t> zstd(ZSTD_compressBound(data.size()));
  zstd.resize(ZSTD_compress(zstd.data(), zstd.size(), data.data(), data.size(), 3));
  std::vector<uint8_t> lz4(LZ4F_compressFrameBound(data.size(), nullptr));
  LZ4F_preferences_t prefs{};
  prefs.frameInfo.blockSizeID = LZ4F_max64KB;
  lz4.resize(LZ4F_compressFrame(lz4.data(), lz4.size(), data.data(), data.size(), &prefs));
  ChunkDecompressor d;
  std::vector<uint8_t> out(data.size());
  for (const auto& [codec, bytes] : {std::pair{ChunkCodec::kZstd, zstd}, std::pair{ChunkCodec::kLz4, lz4}}) {
    const auto whole = d.Run(codec, bytes.data(), bytes.size(), out.data(), out.size(), true);
    EXPECT_TRUE(whole.complete);
    EXPECT_EQ(whole.error, "");
    ASSERT_EQ(whole.produced, data.size());
    EXPECT_EQ(std::memcmp(out.data(), data.data(), data.size()), 0);
    // A cut frame: what it holds up to the cut, a prefix of the data, never more.
    const auto cut = d.Run(codec, bytes.data(), bytes.size() * 2 / 3, out.data(), out.size(), false);
    EXPECT_FALSE(cut.complete);
    EXPECT_GT(cut.produced, 0u);
    EXPECT_LT(cut.produced, data.size());
    EXPECT_EQ(std::memcmp(out.data(), data.data(), cut.produced), 0);
    // Corrupt data: the codec's words, nothing thrown.
    std::vector<uint8_t> bad = bytes;
    bad[bad.size() / 2] ^= 0x5A;
    bad[bad.size() / 2 + 1] ^= 0xA5;
    const auto broken = d.Run(codec, bad.data(), bad.size(), out.data(), out.size(), true);
    EXPECT_TRUE(!broken.error.empty() || !broken.complete || std::memcmp(out.data(), data.data(), data.size()) != 0);
  }
  // A chunk that holds more than it declares.
  const auto small = d.Run(ChunkCodec::kZstd, zstd.data(), zstd.size(), out.data(), 100, true);
  EXPECT_FALSE(small.error.empty());
}

TEST(BagFolder, MetadataYaml) {
  const std::string yaml =
      "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: sqlite3\n"
      "  duration:\n    nanoseconds: 1000\n  topics_with_message_count:\n    - topic_metadata:\n"
      "        name: /imu\n      message_count: 3\n  compression_format: \"\"\n"
      "  compression_mode: \"\"\n  relative_file_paths:\n    - bag_0.db3\n    - 'bag_1.db3'\n"
      "  files:\n    - path: bag_0.db3\n";
  const Ros2BagMetadata m = ParseRos2BagMetadata(yaml, "metadata.yaml");
  EXPECT_EQ(m.storage_identifier, "sqlite3");
  EXPECT_EQ(m.relative_file_paths, (std::vector<std::string>{"bag_0.db3", "bag_1.db3"}));
  EXPECT_EQ(m.compression_format, "");
  const Ros2BagMetadata flow = ParseRos2BagMetadata(
      "rosbag2_bagfile_information:\n  storage_identifier: mcap\n  relative_file_paths: [a.mcap, b.mcap]\n", "m");
  EXPECT_EQ(flow.relative_file_paths, (std::vector<std::string>{"a.mcap", "b.mcap"}));
  EXPECT_THROW(ParseRos2BagMetadata("version: 5\n", "m"), Error);
  EXPECT_THROW(ParseRos2BagMetadata("rosbag2_bagfile_information:\n  storage_identifier: mcap\n", "m"), Error);
}

TEST(BagTimeCheck, MessagesNamedInTheTextReadersWords) {
  detail::SampleTimeCheck text("rec.txt", true);
  detail::SampleTimeCheck bag("imu.mcap", true);
  bag.NameMessages("/imu");
  std::vector<Sample> out;
  std::vector<InputError> text_errors, bag_errors;
  for (double t : {1.0, 2.0, 1.5}) {
    Sample s;
    s.t_s = t;
    text.Add(s, "1.5 1 2 3", static_cast<long>(out.size()) + 1, 0, &out, &text_errors);
    bag.Add(s, {}, static_cast<long>(out.size()), 0, &out, &bag_errors);
  }
  ASSERT_EQ(text_errors.size(), 1u);
  ASSERT_EQ(bag_errors.size(), 1u);
  EXPECT_TRUE(Contains(text_errors[0].what(), "t = 1.5 s does not increase (line "));
  EXPECT_EQ(std::string(bag_errors[0].what()).rfind("imu.mcap: /imu message ", 0), 0u) << bag_errors[0].what();
  EXPECT_TRUE(Contains(bag_errors[0].what(), ": t = 1.5 s does not increase (message ")) << bag_errors[0].what();
  EXPECT_TRUE(Contains(bag_errors[0].what(), " has t = 2 s); t must be strictly increasing"));
}

// A minimal MCAP, laid out from the specification: header, a chunk (uncompressed, with its
// CRC) holding a schema, a channel and two Imu messages, then a Data End; no summary.
std::vector<uint8_t> TinyMcap(bool good_crc, bool two_messages = true) {
  std::vector<uint8_t> f = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
  const auto record = [](std::vector<uint8_t>* out, uint8_t op, const std::vector<uint8_t>& body) {
    out->push_back(op);
    PutLittle(out, body.size(), 8);
    out->insert(out->end(), body.begin(), body.end());
  };
  const auto str = [](std::vector<uint8_t>* out, const std::string& s) {
    PutLittle(out, s.size(), 4);
    out->insert(out->end(), s.begin(), s.end());
  };
  std::vector<uint8_t> header;
  str(&header, "ros2");
  str(&header, "bags_test");
  record(&f, 0x01, header);
  std::vector<uint8_t> records;
  std::vector<uint8_t> schema;
  PutLittle(&schema, 1, 2);
  str(&schema, "sensor_msgs/msg/Imu");
  str(&schema, "ros2msg");
  str(&schema, "");
  record(&records, 0x03, schema);
  std::vector<uint8_t> channel;
  PutLittle(&channel, 3, 2);
  PutLittle(&channel, 1, 2);
  str(&channel, "/imu");
  str(&channel, "cdr");
  PutLittle(&channel, 0, 4);
  record(&records, 0x04, channel);
  for (int i = 0; i < (two_messages ? 2 : 1); ++i) {
    std::vector<uint8_t> message;
    PutLittle(&message, 3, 2);
    PutLittle(&message, static_cast<uint64_t>(i), 4);
    PutLittle(&message, 1000000000ull + i, 8);
    PutLittle(&message, 1000000000ull + i, 8);
    const std::vector<uint8_t> imu = CdrImu(100, static_cast<uint32_t>(i) * 10000000u, "imu", 0.1 * i, 0.2, 9.8, false);
    message.insert(message.end(), imu.begin(), imu.end());
    record(&records, 0x05, message);
  }
  std::vector<uint8_t> chunk;
  PutLittle(&chunk, 1000000000ull, 8);
  PutLittle(&chunk, 1000000001ull, 8);
  PutLittle(&chunk, records.size(), 8);
  PutLittle(&chunk, Crc32(records.data(), records.size()) + (good_crc ? 0 : 1), 4);
  str(&chunk, "");
  PutLittle(&chunk, records.size(), 8);
  chunk.insert(chunk.end(), records.begin(), records.end());
  record(&f, 0x06, chunk);
  std::vector<uint8_t> data_end;
  PutLittle(&data_end, 0, 4);
  record(&f, 0x0F, data_end);
  return f;
}

std::string WriteTemp(const std::vector<uint8_t>& bytes, const std::string& name) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                              static_cast<std::streamsize>(bytes.size()));
  return path;
}

TEST(BagMcap, TinyFileReadAndItsDamage) {
  const std::string good = WriteTemp(TinyMcap(true), "tiny.mcap");
  BagSampleStream stream(good, SampleFormat{});
  std::vector<Sample> samples;
  while (stream.Next(&samples)) {
  }
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[1].t_s, 100.01);
  EXPECT_EQ(samples[1].raw_counts.x(), 0.1 * 1000.0);  // m/s^2 as counts of 0.001 m/s^2
  EXPECT_TRUE(Contains(stream.Summary().Describe(), "topic /imu (sensor_msgs/msg/Imu); MCAP file, uncompressed chunks"));

  const std::string bad = WriteTemp(TinyMcap(false), "bad_crc.mcap");
  try {
    BagSampleStream s(bad, SampleFormat{});
    std::vector<Sample> v;
    while (s.Next(&v)) {
    }
    ADD_FAILURE() << "a bad CRC read";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "chunk 1 (at byte 38): its records' CRC-32 is ")) << e.what();
  }

  // Cut inside the second message: the first is read, and the cut said.
  std::vector<uint8_t> cut = TinyMcap(true);
  cut.resize(cut.size() - 13 - 100);
  BagSampleStream c(WriteTemp(cut, "cut.mcap"), SampleFormat{});
  std::vector<Sample> v;
  while (c.Next(&v)) {
  }
  EXPECT_EQ(v.size(), 1u);
  EXPECT_TRUE(Contains(c.Summary().Describe(), "read up to its last whole message")) << c.Summary().Describe();
}

}  // namespace
}  // namespace accelcal::bags

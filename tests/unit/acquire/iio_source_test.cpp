// The IIO source on a tree of files in a temporary directory (as the e2e tests do with the
// virtual bench behind it): the buffer0/ layout with a FIFO as the device file, records decoded
// from their scan types, the scan elements enabled and the others disabled, the sampling
// frequency set and read back, an overrun named; polling of *_raw, a read that fails with EIO
// (a link to /proc/self/mem, which reads EIO at offset 0), a device that goes away.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "accelcal/acquire/iio/iio_source.h"
#include "source_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;
using testing::Contains;
using testing::ReadUntil;

void PutAttr(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text << "\n";
}

std::string GetAttr(const fs::path& file) {
  std::ifstream in(file);
  std::string text;
  std::getline(in, text);
  return text;
}

class IioSourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / fmt::format("accelcal_iio_{}_{}", ::getpid(),
                                                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    dev_ = root_ / "iio:device3";
    PutAttr(dev_ / "name", "adxl345");
    PutAttr(dev_ / "in_accel_scale", "0.038307");
    PutAttr(dev_ / "sampling_frequency", "100");
    PutAttr(dev_ / "trigger/current_trigger", "adxl345-dev3");
    for (const char* axis : {"x", "y", "z"}) PutAttr(dev_ / fmt::format("in_accel_{}_raw", axis), "0");
  }
  void TearDown() override { fs::remove_all(root_); }

  void Buffer0() {
    PutAttr(dev_ / "buffer0/enable", "0");
    PutAttr(dev_ / "buffer0/length", "64");
    int index = 0;
    for (const char* axis : {"x", "y", "z"}) {
      PutAttr(dev_ / fmt::format("buffer0/in_accel_{}_en", axis), "0");
      PutAttr(dev_ / fmt::format("buffer0/in_accel_{}_index", axis), std::to_string(index++));
      PutAttr(dev_ / fmt::format("buffer0/in_accel_{}_type", axis), "le:s12/16>>4");
    }
    PutAttr(dev_ / "buffer0/in_timestamp_en", "0");
    PutAttr(dev_ / "buffer0/in_timestamp_index", "3");
    PutAttr(dev_ / "buffer0/in_timestamp_type", "le:s64/64>>0");
    PutAttr(dev_ / "buffer0/in_temp_en", "1");  // enabled by someone else: must be turned off
    PutAttr(dev_ / "buffer0/in_temp_index", "4");
    PutAttr(dev_ / "buffer0/in_temp_type", "le:s16/16>>0");
    fifo_ = root_ / "dev-fifo";
    ASSERT_EQ(::mkfifo(fifo_.c_str(), 0600), 0);
  }

  // Writes records (x, y, z counts; timestamp ns) to the FIFO from a thread, then closes it.
  std::thread Feed(std::vector<std::array<std::int64_t, 4>> records) {
    return std::thread([this, records] {
      const int fd = ::open(fifo_.c_str(), O_WRONLY);
      for (const auto& r : records) {
        std::uint8_t b[16] = {};
        for (int j = 0; j < 3; ++j) {
          const auto v = static_cast<std::uint16_t>(static_cast<std::uint16_t>(r[static_cast<size_t>(j)]) << 4);
          std::memcpy(b + 2 * j, &v, 2);
        }
        std::memcpy(b + 8, &r[3], 8);
        (void)!::write(fd, b, sizeof b);
      }
      ::close(fd);
    });
  }

  IioSourceSpec Spec(const std::string& extra = "") {
    return ParseIioSpec(fmt::format("iio:adxl345,root={},dev={}{}", root_.string(), fifo_.string(), extra));
  }

  fs::path root_, dev_, fifo_;
};

SourceOptions Quick() {
  SourceOptions o;
  o.reconnect_initial_s = 0.05;
  o.dead_after_s = 5.0;
  return o;
}

TEST_F(IioSourceTest, BufferedRecordsDecodedWithTheirTimestamps) {
  Buffer0();
  std::vector<std::array<std::int64_t, 4>> records;
  for (int k = 0; k < 50; ++k) {
    if (k == 30) continue;  // lost: the timestamps jump by two periods
    records.push_back({-5 + k % 3, 250, -2048, 1'000'000'000LL + 10'000'000LL * k});
  }
  std::thread feeder = Feed(records);
  SourceOptions quick = Quick();
  quick.dead_after_s = 1.0;
  IioSource source(Spec(",rate=100"), quick);
  std::vector<Sample> samples;
  ReadResult events;
  ReadUntil(source, &samples, [](const SourceStatus& s) { return s.link == LinkState::kDead; }, 20.0, &events);
  feeder.join();
  ASSERT_EQ(samples.size(), 49u);
  EXPECT_EQ(samples[0].raw_counts.x(), -5.0);
  EXPECT_EQ(samples[0].raw_counts.y(), 250.0);
  EXPECT_EQ(samples[0].raw_counts.z(), -2048.0);
  EXPECT_DOUBLE_EQ(samples[29].t_s, 0.29);
  EXPECT_DOUBLE_EQ(samples[30].t_s, 0.31);
  EXPECT_EQ(source.status().lost_frames, 1);
  EXPECT_TRUE(Contains(source.DescribeReading(), "1 overrun, 1 samples lost")) << source.DescribeReading();
  EXPECT_EQ(GetAttr(dev_ / "buffer0/in_accel_y_en"), "1");
  EXPECT_EQ(GetAttr(dev_ / "buffer0/in_timestamp_en"), "1");
  EXPECT_EQ(GetAttr(dev_ / "buffer0/in_temp_en"), "0");
  EXPECT_EQ(GetAttr(dev_ / "buffer0/enable"), "1");
  EXPECT_TRUE(Contains(source.DescribeReading(), "in_accel_scale 0.038307 and no offset stated, not applied"))
      << source.DescribeReading();
  EXPECT_TRUE(Contains(source.DescribeReading(), "trigger: adxl345-dev3"));
  EXPECT_TRUE(events.link_lost);
  EXPECT_TRUE(Contains(source.status().link_error, "dev-fifo ended: the device stopped delivering"))
      << source.status().link_error;
}

TEST_F(IioSourceTest, AScanTypeNotUnderstoodIsRefusedByName) {
  Buffer0();
  PutAttr(dev_ / "buffer0/in_accel_z_type", "le:s12/12>>4");
  try {
    IioSource source(Spec(), Quick());
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "iio:device3 (adxl345): in_accel_z_type: scan type 'le:s12/12>>4' not understood"))
        << e.what();
  }
}

TEST_F(IioSourceTest, PolledRawFilesAnEioReadAndADeviceThatGoesAway) {
  PutAttr(dev_ / "in_accel_x_raw", "12");
  PutAttr(dev_ / "in_accel_y_raw", "-7");
  PutAttr(dev_ / "in_accel_z_raw", "1002");
  IioSource source(ParseIioSpec(fmt::format("iio:iio:device3,root={},rate=200", root_.string())), Quick());
  EXPECT_FALSE(source.buffered());
  std::vector<Sample> samples;
  ASSERT_TRUE(ReadUntil(source, &samples, [](const SourceStatus& s) { return s.samples_total >= 20; }));
  EXPECT_EQ(samples.back().raw_counts, Eigen::Vector3d(12, -7, 1002));
  // -EIO from the driver: a read that fails.
  fs::remove(dev_ / "in_accel_y_raw");
  fs::create_symlink("/proc/self/mem", dev_ / "in_accel_y_raw");
  ASSERT_TRUE(ReadUntil(source, &samples, [](const SourceStatus& s) { return s.malformed_lines >= 3; }));
  EXPECT_TRUE(Contains(source.status().last_malformed, "in_accel_y_raw: read: Input/output error"))
      << source.status().last_malformed;
  fs::remove_all(dev_);
  ReadResult events;
  ASSERT_TRUE(ReadUntil(source, &samples, [](const SourceStatus& s) { return s.link == LinkState::kDead; }, 20.0, &events));
  EXPECT_TRUE(Contains(source.status().link_error, "the device went away")) << source.status().link_error;
}

}  // namespace
}  // namespace accelcal

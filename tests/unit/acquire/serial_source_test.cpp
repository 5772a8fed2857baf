// serial:DEVICE@BAUD through a pseudo-terminal pair: lines written to the master arrive through
// the slave; closing the master is a cut cable.
#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "accelcal/acquire/source/source_spec.h"
#include "source_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Consecutive;
using testing::Contains;
using testing::ReadUntil;
using testing::SampleLines;
using testing::WriteAll;

class SerialSourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    master_ = posix_openpt(O_RDWR | O_NOCTTY);
    ASSERT_GE(master_, 0);
    ASSERT_EQ(grantpt(master_), 0);
    ASSERT_EQ(unlockpt(master_), 0);
    const char* name = ptsname(master_);
    ASSERT_NE(name, nullptr);
    slave_path_ = name;
  }
  void TearDown() override { CloseMaster(); }
  void CloseMaster() {
    if (master_ >= 0) ::close(master_);
    master_ = -1;
  }
  std::unique_ptr<SampleSource> OpenUp(std::vector<Sample>* samples) {
    SourceOptions options;
    options.dead_after_s = 0.5;
    options.reconnect_initial_s = 0.05;
    auto source = OpenSource("serial:" + slave_path_ + "@115200", options);
    EXPECT_TRUE(ReadUntil(*source, samples, [](const SourceStatus& s) { return s.link == LinkState::kUp; }))
        << source->status().link_error;
    return source;
  }

  int master_ = -1;
  std::string slave_path_;
};

TEST_F(SerialSourceTest, LinesWrittenToThePortArrive) {
  std::vector<Sample> samples;
  auto source = OpenUp(&samples);
  ASSERT_TRUE(WriteAll(master_, SampleLines(0, 300)));
  ASSERT_TRUE(ReadUntil(*source, &samples, [](const SourceStatus& s) { return s.samples_total >= 300; }));
  EXPECT_EQ(samples.size(), 300u);
  EXPECT_TRUE(Consecutive(samples));
  EXPECT_NEAR(source->status().rate_hz, 100.0, 1e-6);
  EXPECT_EQ(source->status().malformed_lines, 0);
}

TEST_F(SerialSourceTest, GarbageBytesAreMalformedNotFatal) {
  std::vector<Sample> samples;
  auto source = OpenUp(&samples);
  std::string noise;
  for (int i = 0; i < 600; ++i) noise += static_cast<char>((i * 37 + 11) % 251 + 1);
  ASSERT_TRUE(WriteAll(master_, SampleLines(0, 10) + noise + "\n" + SampleLines(10, 10)));
  ASSERT_TRUE(ReadUntil(*source, &samples, [](const SourceStatus& s) { return s.samples_total >= 20; }));
  EXPECT_TRUE(Consecutive(samples));
  EXPECT_GE(source->status().malformed_lines, 1);
}

TEST_F(SerialSourceTest, CutCableIsADeadLinkWithTheReason) {
  std::vector<Sample> samples;
  auto source = OpenUp(&samples);
  ASSERT_TRUE(WriteAll(master_, SampleLines(0, 50)));
  ASSERT_TRUE(ReadUntil(*source, &samples, [](const SourceStatus& s) { return s.samples_total >= 50; }));
  CloseMaster();  // the cable is cut
  ReadResult events;
  ASSERT_TRUE(ReadUntil(*source, &samples,
                        [](const SourceStatus& s) { return s.link == LinkState::kDead; }, 30.0,
                        &events));
  EXPECT_TRUE(events.went_dead);
  const std::string& why = source->status().link_error;
  EXPECT_FALSE(why.empty());
  EXPECT_TRUE(Contains(why, slave_path_)) << why;
  // Reopen attempts go on (and fail) without ever leaving the dead state or throwing.
  ReadUntil(*source, &samples, [](const SourceStatus&) { return false; }, 0.5);
  EXPECT_EQ(source->status().link, LinkState::kDead);
  EXPECT_EQ(samples.size(), 50u);
}

TEST(SerialSourceMissingDeviceTest, AbsentPortIsRetriedAndReportedDead) {
  SourceOptions options;
  options.dead_after_s = 0.2;
  options.reconnect_initial_s = 0.05;
  auto source = OpenSource("serial:/dev/accelcal-no-such-port@9600", options);
  std::vector<Sample> samples;
  ASSERT_TRUE(ReadUntil(*source, &samples, [](const SourceStatus& s) { return s.link == LinkState::kDead; }));
  EXPECT_TRUE(Contains(source->status().link_error,
                       "open /dev/accelcal-no-such-port: No such file or directory"))
      << source->status().link_error;
}

}  // namespace
}  // namespace accelcal

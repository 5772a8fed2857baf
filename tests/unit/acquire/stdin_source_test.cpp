// The "-" source, read through a pipe: a burst, garbage, a gap in t, a dead link, the end.
#include <fcntl.h>
#include <unistd.h>

#include <random>
#include <thread>

#include <gtest/gtest.h>

#include "accelcal/acquire/source/source_spec.h"
#include "source_test_support.h"
#include "test_support.h"

namespace accelcal::stdin_source_test {
namespace {

using testing::Consecutive;
using testing::Contains;
using testing::ReadUntil;
using testing::SampleLines;
using testing::WriteAll;

// A pipe whose read end is the source's standard input.
class StdinSourceTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(pipe2(fds_, O_CLOEXEC), 0); }
  void TearDown() override {
    CloseWriter();
    ::close(fds_[0]);
  }
  std::unique_ptr<SampleSource> Open(SourceOptions options = {}) {
    options.stdin_fd = fds_[0];
    return OpenSource("-", options);
  }
  void CloseWriter() {
    if (fds_[1] >= 0) ::close(fds_[1]);
    fds_[1] = -1;
  }
  int writer() const { return fds_[1]; }

 private:
  int fds_[2] = {-1, -1};
};

bool Ended(const SourceStatus& s) { return s.link == LinkState::kEnded; }

TEST_F(StdinSourceTest, BurstOf100kLinesArrivesCompleteAndInOrder) {
  auto source = Open();
  const std::string burst = SampleLines(0, 100000, 1000.0);
  std::thread writer([&] {
    EXPECT_TRUE(WriteAll(this->writer(), burst));
    CloseWriter();
  });
  std::vector<Sample> samples;
  ReadResult events;
  const bool ended = ReadUntil(*source, &samples, Ended, 60.0, &events);
  writer.join();
  ASSERT_TRUE(ended);
  ASSERT_EQ(samples.size(), 100000u);
  EXPECT_TRUE(Consecutive(samples));
  EXPECT_TRUE(events.ended);
  EXPECT_EQ(source->status().samples_total, 100000);
  EXPECT_EQ(source->status().malformed_lines, 0);
  EXPECT_EQ(source->status().gaps, 0);
  EXPECT_NEAR(source->status().rate_hz, 1000.0, 1e-6);
}

TEST_F(StdinSourceTest, GarbageIsCountedAndTheGoodLinesAroundItSurvive) {
  auto source = Open();
  std::mt19937 rng(11);
  std::string binary(5000, '\0');
  for (char& c : binary) c = static_cast<char>(rng() & 0xff);
  const std::string text = SampleLines(0, 100) + binary + "\n" + SampleLines(100, 100) +
                           std::string(10 * 1024, 'A') + "\n" + SampleLines(200, 100) +
                           "0.3x 1 2 3\n";
  std::thread writer([&] {
    EXPECT_TRUE(WriteAll(this->writer(), text));
    CloseWriter();
  });
  std::vector<Sample> samples;
  ReadResult events;
  ASSERT_TRUE(ReadUntil(*source, &samples, Ended, 30.0, &events));
  writer.join();
  ASSERT_EQ(samples.size(), 300u);
  EXPECT_TRUE(Consecutive(samples));
  EXPECT_GE(source->status().malformed_lines, 3);
  EXPECT_EQ(events.malformed, source->status().malformed_lines);
  const std::string& last = source->status().last_malformed;
  EXPECT_EQ(last.rfind("line ", 0), 0u) << last;
  EXPECT_TRUE(Contains(last, ", column 1: field 't': '0.3x' is not a number")) << last;
}

TEST_F(StdinSourceTest, GapInTimeIsReportedWithItsSize) {
  auto source = Open();
  // 100 Hz, then 2.5 s with nothing, then 100 Hz again.
  const std::string text = SampleLines(0, 100) + SampleLines(100, 100, 100.0, 2.5);
  ASSERT_TRUE(WriteAll(writer(), text));
  CloseWriter();
  std::vector<Sample> samples;
  ReadResult events;
  ASSERT_TRUE(ReadUntil(*source, &samples, Ended, 30.0, &events));
  EXPECT_EQ(events.gaps, 1);
  const SourceStatus& s = source->status();
  EXPECT_EQ(s.gaps, 1);
  EXPECT_DOUBLE_EQ(s.last_gap.t_before_s, 0.99);
  EXPECT_DOUBLE_EQ(s.last_gap.t_after_s, 3.5);
  EXPECT_NEAR(s.last_gap.missing_s, 2.5, 1e-6);
}

TEST_F(StdinSourceTest, SilenceMakesTheLinkDeadAndDataRevivesIt) {
  SourceOptions options;
  options.dead_after_s = 0.2;
  auto source = Open(options);
  ASSERT_TRUE(WriteAll(writer(), SampleLines(0, 10)));
  std::vector<Sample> samples;
  ASSERT_TRUE(ReadUntil(*source, &samples, [](const SourceStatus& s) { return s.samples_total == 10; }));
  EXPECT_EQ(source->status().link, LinkState::kUp);
  ReadResult events;
  ASSERT_TRUE(ReadUntil(*source, &samples,
                        [](const SourceStatus& s) { return s.link == LinkState::kDead; }, 30.0,
                        &events));
  EXPECT_TRUE(events.went_dead);
  EXPECT_TRUE(Contains(source->status().link_error, "no sample for")) << source->status().link_error;
  EXPECT_GE(source->status().since_last_sample_s, 0.2);
  ReadResult back;
  ASSERT_TRUE(WriteAll(writer(), SampleLines(10, 10)));
  ASSERT_TRUE(ReadUntil(*source, &samples, [](const SourceStatus& s) { return s.samples_total == 20; },
                        30.0, &back));
  EXPECT_TRUE(back.reconnected);
  EXPECT_EQ(source->status().link, LinkState::kUp);
  EXPECT_TRUE(Consecutive(samples));
}

TEST_F(StdinSourceTest, ReadNeverBlocksPastItsTimeout) {
  auto source = Open();
  std::vector<Sample> samples;
  const auto start = std::chrono::steady_clock::now();
  const ReadResult r = source->Read(0.05, &samples);
  const double waited_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.samples, 0);
  EXPECT_LT(waited_s, 5.0);  // generous: the point is that it returns at all
}

}  // namespace
}  // namespace accelcal::stdin_source_test

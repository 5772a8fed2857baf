// file:PATH: replay as fast as possible or paced by t; the end of the file ends the source.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>

#include "accelcal/acquire/source/source_spec.h"
#include "source_test_support.h"

namespace accelcal {
namespace {

using testing::Consecutive;
using testing::ReadUntil;
using testing::SampleLines;

std::string TempFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "accelcal_" + std::to_string(::getpid()) + "_" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

bool Ended(const SourceStatus& s) { return s.link == LinkState::kEnded; }

TEST(FileSourceTest, FastReplayDeliversEverySampleInOrderThenEnds) {
  const std::string path =
      TempFile("fast.txt", "# recorded\n" + SampleLines(0, 5000) + "0.1x 1 2 3\n" + SampleLines(5000, 10));
  auto source = OpenSource("file:" + path, {});
  EXPECT_EQ(source->Describe(), "file:" + path);
  std::vector<Sample> samples;
  ReadResult events;
  ASSERT_TRUE(ReadUntil(*source, &samples, Ended, 30.0, &events));
  ASSERT_EQ(samples.size(), 5010u);
  EXPECT_TRUE(Consecutive(samples));
  EXPECT_TRUE(events.ended);
  EXPECT_EQ(source->status().malformed_lines, 1);
  // Ended stays ended, and Read returns at once.
  const ReadResult again = source->Read(10.0, &samples);
  EXPECT_EQ(again.samples, 0);
  EXPECT_FALSE(again.ended);  // the event was reported once
  EXPECT_EQ(source->status().link, LinkState::kEnded);
  std::remove(path.c_str());
}

TEST(FileSourceTest, RealtimeReplayIsPacedByTAndKeepsOrder) {
  const std::string path = TempFile("paced.txt", SampleLines(0, 40));  // 0.4 s at 100 Hz
  SourceOptions options;
  options.realtime = true;
  auto source = OpenSource("file:" + path, options);
  std::vector<Sample> samples;
  // The first delivery is the first sample alone: the others are not due yet.
  const ReadResult first = source->Read(5.0, &samples);
  EXPECT_EQ(first.samples, 1);
  ASSERT_TRUE(ReadUntil(*source, &samples, Ended));
  ASSERT_EQ(samples.size(), 40u);
  EXPECT_TRUE(Consecutive(samples));
  std::remove(path.c_str());
}

// Issue 18: a paced replay of a 10 kHz recording delivered each sample as it fell due, one read
// (and one wake-up of the wizard's loop) per sample; deliveries are now at least 5 ms apart, so
// 0.2 s of replay takes at most ~40 reads however fast the machine, every sample in order.
TEST(FileSourceTest, APacedFastReplayComesInBurstsNotOneReadPerSample) {
  std::string text;
  for (int i = 0; i < 5000; ++i) text += std::to_string(i * 1e-4) + " 1 2000 3000\n";  // 0.5 s
  const std::string path = TempFile("paced10k.txt", text);
  SourceOptions options;
  options.realtime = true;
  auto source = OpenSource("file:" + path, options);
  std::vector<Sample> samples;
  int reads = 0;
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(200)) {
    source->Read(1.0, &samples);
    ++reads;
  }
  EXPECT_LE(reads, 42);
  ASSERT_GT(samples.size(), 1u);
  for (size_t i = 1; i < samples.size(); ++i)
    ASSERT_NEAR(samples[i].t_s - samples[i - 1].t_s, 1e-4, 1e-9) << "sample " << i;
  std::remove(path.c_str());
}

TEST(FileSourceTest, LastLineWithoutNewlineIsRead) {
  const std::string path = TempFile("nonl.txt", "0 0 2000 3000\n0.01 1 2000 3000");
  auto source = OpenSource("file:" + path, {});
  std::vector<Sample> samples;
  ASSERT_TRUE(ReadUntil(*source, &samples, Ended));
  EXPECT_EQ(samples.size(), 2u);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace accelcal

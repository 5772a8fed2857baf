// file:PATH: replay as fast as possible or paced by t; the end of the file ends the source.
#include <unistd.h>

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

// LineStream: lines split across reads, malformed lines counted and named, garbage skipped.
#include "accelcal/acquire/source/line_stream.h"

#include <random>

#include <gtest/gtest.h>

#include "source_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Contains;
using testing::SampleLines;

struct Fed {
  std::vector<Sample> samples;
  long malformed = 0;
  std::string last_malformed;
};

// Feeds `text` in pieces of `piece` bytes, then finishes.
Fed FeedInPieces(const std::string& text, size_t piece, long max_line_bytes = 256) {
  LineStream stream("test", max_line_bytes);
  Fed fed;
  for (size_t i = 0; i < text.size(); i += piece) {
    LineStream::FeedResult r;
    stream.Feed(std::string_view(text).substr(i, piece), &fed.samples, &r);
    fed.malformed += r.malformed;
    if (!r.last_malformed.empty()) fed.last_malformed = r.last_malformed;
  }
  LineStream::FeedResult r;
  stream.Finish(&fed.samples, &r);
  fed.malformed += r.malformed;
  if (!r.last_malformed.empty()) fed.last_malformed = r.last_malformed;
  return fed;
}

TEST(LineStreamTest, SameSamplesWhateverTheReadSize) {
  const std::string text = "# header\n" + SampleLines(0, 50) + "\r\n0.5, 50, 2000, 3000\r\n";
  for (size_t piece : {1, 2, 7, 64, 100000}) {
    const Fed fed = FeedInPieces(text, piece);
    ASSERT_EQ(fed.samples.size(), 51u) << "piece " << piece;
    EXPECT_TRUE(testing::Consecutive(fed.samples));
    EXPECT_EQ(fed.malformed, 0);
    EXPECT_DOUBLE_EQ(fed.samples[50].t_s, 0.5);
  }
}

TEST(LineStreamTest, MalformedLinesAreCountedWithLineAndColumn) {
  const std::string text = SampleLines(0, 3) + "0.03 3 x 3000\n" + SampleLines(4, 2);
  const Fed fed = FeedInPieces(text, 5);
  EXPECT_EQ(fed.samples.size(), 5u);
  EXPECT_EQ(fed.malformed, 1);
  EXPECT_EQ(fed.last_malformed, "line 4, column 8: field 'ay': 'x' is not a number");
}

TEST(LineStreamTest, TimeNotIncreasingIsMalformed) {
  const std::string text = SampleLines(0, 3) + "0.01 9 9 9\n" + SampleLines(3, 1);
  const Fed fed = FeedInPieces(text, 4096);
  EXPECT_EQ(fed.samples.size(), 4u);
  EXPECT_EQ(fed.malformed, 1);
  EXPECT_TRUE(Contains(fed.last_malformed, "does not increase")) << fed.last_malformed;
}

TEST(LineStreamTest, LastLineWithoutNewlineCountsAtTheEnd) {
  const Fed fed = FeedInPieces("0 1 2 3\n0.01 1 2 3", 3);
  EXPECT_EQ(fed.samples.size(), 2u);
}

TEST(LineStreamTest, DiscardPartialDropsAFragment) {
  LineStream stream("test", 256);
  std::vector<Sample> samples;
  LineStream::FeedResult r;
  stream.Feed("0 1 2 3\n0.01 1 2", &samples, &r);  // the link drops mid-line
  stream.DiscardPartial();
  stream.Feed("0.02 1 2 3\n", &samples, &r);
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_DOUBLE_EQ(samples[1].t_s, 0.02);
  EXPECT_EQ(r.malformed, 0);
}

TEST(LineStreamTest, OverlongLineIsOneMalformedLineAndTheNextLinesSurvive) {
  const std::string text = SampleLines(0, 10) + std::string(10000, '7') + "\n" + SampleLines(10, 10);
  for (size_t piece : {1, 13, 4096, 100000}) {
    const Fed fed = FeedInPieces(text, piece);
    EXPECT_EQ(fed.samples.size(), 20u) << "piece " << piece;
    EXPECT_TRUE(testing::Consecutive(fed.samples));
    EXPECT_EQ(fed.malformed, 1) << "piece " << piece;
    EXPECT_TRUE(Contains(fed.last_malformed, "more than 256 bytes")) << fed.last_malformed;
  }
}

TEST(LineStreamTest, RandomBinaryGarbageNeverLosesTheGoodLinesAround) {
  std::mt19937 rng(7);
  std::string garbage(20000, '\0');
  for (char& c : garbage) c = static_cast<char>(rng() & 0xff);
  const std::string text = SampleLines(0, 100) + garbage + "\n" + SampleLines(100, 100);
  const Fed fed = FeedInPieces(text, 997);
  EXPECT_EQ(fed.samples.size(), 200u);
  EXPECT_TRUE(testing::Consecutive(fed.samples));
  EXPECT_GT(fed.malformed, 0);
  for (char c : fed.last_malformed) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "unprintable in message";
}

TEST(LineStreamTest, PrintableTextReplacesControlBytes) {
  EXPECT_EQ(PrintableText(std::string("a\x01\xff" "b", 4)), "a??b");
  EXPECT_EQ(PrintableText("abcdef", 3), "abc...");
}

}  // namespace
}  // namespace accelcal

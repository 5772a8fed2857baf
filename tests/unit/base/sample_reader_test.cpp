// The one sample reader (issue 14): the shapes of files from the field, and what it refuses.
#include "accelcal/base/sample_reader.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

std::vector<Sample> ReadAll(const std::string& text, const SampleFormat& format = {},
                            ReadingSummary* summary = nullptr) {
  SampleReader reader("test.txt", format, SampleReader::OnMalformed::kThrow);
  std::vector<Sample> out;
  const size_t used = reader.Consume(text, true, &out);
  EXPECT_EQ(used, text.size());
  reader.Finish(&out);
  if (summary != nullptr) *summary = reader.Summary();
  return out;
}

TEST(SampleReader, ProtocolColumnsWithBlanks) {
  const auto s = ReadAll("0 1 2 3\n0.01 4 5 6\n");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[1].t_s, 0.01);
  EXPECT_EQ(s[1].raw_counts, Eigen::Vector3d(4, 5, 6));
}

TEST(SampleReader, BomCrlfSemicolonsTabsAndComments) {
  // One separator per file, whichever it is; comments and blank lines anywhere.
  for (const std::string sep : {";", "\t", ",", " "}) {
    const auto s = ReadAll("\xEF\xBB\xBF# a comment\r\n0" + sep + "1" + sep + "2" + sep + "3\r\n\r\n# c\r\n0.01" +
                           sep + "7" + sep + "8" + sep + "9\r\n");
    ASSERT_EQ(s.size(), 2u) << "separator '" << sep << "'";
    EXPECT_EQ(s[1].raw_counts, Eigen::Vector3d(7, 8, 9)) << "separator '" << sep << "'";
  }
}

TEST(SampleReader, HeaderNamesGyroFirstColumns) {
  ReadingSummary sum;
  const auto s = ReadAll("t gx gy gz ax ay az\n0 0.1 0.2 0.3 10 20 30\n0.01 0.1 0.2 0.3 11 21 31\n", {}, &sum);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].raw_counts, Eigen::Vector3d(10, 20, 30));
  EXPECT_EQ(sum.ignored.size(), 3u);
  EXPECT_NE(sum.Describe().find("gx"), std::string::npos) << sum.Describe();
}

TEST(SampleReader, CommonSpellingsInTheHeader) {
  const std::string text = "Timestamp,AccX [m/s^2],acc_y,accel_z,Temperature\n0,1,2,3,25.5\n";
  // The header states m/s^2: not taken silently as counts.
  EXPECT_THROW(ReadAll(text), Error);
  SampleFormat f;
  f.unit = *StringToReadingUnit("m/s^2");
  f.unit_declared = true;
  const auto s = ReadAll(text, f);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_NEAR(s[0].raw_counts.x(), 1000.0, 1e-9);  // counts of 0.001 m/s^2
  EXPECT_DOUBLE_EQ(s[0].temp_c, 25.5);
}

TEST(SampleReader, ColumnsGivenSkipRowsAndRate) {
  SampleFormat f;
  std::string error;
  f.columns = ParseColumnList("ax,ay,az,-,-,-", &error);
  ASSERT_TRUE(error.empty()) << error;
  f.skip_rows = 2;
  f.rate_hz = 50.0;
  const auto s = ReadAll("sketch,MPU6050\nrate_hz,50\n1,2,3,9,9,9\n4,5,6,9,9,9\n7,8,9,9,9,9\n", f);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_DOUBLE_EQ(s[2].t_s, 0.04);
  EXPECT_EQ(s[2].raw_counts, Eigen::Vector3d(7, 8, 9));
}

TEST(SampleReader, MetadataWithoutRateIsRefusedWithAReason) {
  EXPECT_THROW(ReadAll("sketch,MPU6050\nax,ay,az\n1,2,3\n"), Error);
}

// A logger that prints t with two decimals at 200 Hz: 0, 0, 0.01, 0.01, ... (ties). Repaired
// within their step and counted; a t that goes back stays an error.
TEST(SampleReader, RepeatedStampsOfARoundingLoggerAreRepaired) {
  std::string text;
  for (int i = 0; i < 400; ++i) text += std::to_string(std::floor(i * 0.5) / 100.0) + " 1 2 3\n";
  ReadingSummary sum;
  const auto s = ReadAll(text, {}, &sum);
  ASSERT_EQ(s.size(), 400u);
  for (size_t i = 1; i < s.size(); ++i) ASSERT_GT(s[i].t_s, s[i - 1].t_s) << i;
  EXPECT_NEAR(s[399].t_s - s[0].t_s, 399 * 0.005, 0.011);
  EXPECT_GT(sum.repaired_ties, 0);
  EXPECT_NE(sum.Describe().find("repeated time stamp"), std::string::npos) << sum.Describe();
}

TEST(SampleReader, TimeThatGoesBackIsAnError) {
  EXPECT_THROW(ReadAll("0 1 2 3\n0.02 1 2 3\n0.01 1 2 3\n"), InputError);
}

TEST(SampleReader, TiesRefusedWithoutRepair) {
  SampleFormat f;
  f.repair_ties = false;
  EXPECT_THROW(ReadAll("0 1 2 3\n0 1 2 3\n0.01 1 2 3\n", f), InputError);
}

// Issue 17 item 8: a binary file (no newline in megabytes) stops at the line limit, and the
// error quotes a short excerpt only.
TEST(SampleReader, BinaryInputStopsEarlyWithAShortMessage) {
  const std::string nul(1 << 20, '\0');
  try {
    ReadAll(nul);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_LT(std::string(e.what()).size(), 400u) << e.what();
  }
  SampleReader live("link", SampleFormat{}, SampleReader::OnMalformed::kSkip);
  std::vector<Sample> out;
  live.Feed(std::string(100000, 'x'), &out);
  live.Feed("\n0 1 2 3\n", &out);
  live.Finish(&out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(live.malformed(), 1);
}

}  // namespace
}  // namespace accelcal

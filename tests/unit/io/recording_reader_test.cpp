#include "accelcal/io/recording_reader.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "test_support.h"

#include "accelcal/base/error.h"

namespace accelcal::recording_reader_test {
namespace {

// Parses `text` expecting an InputError; returns it.
InputError ParseFailure(const std::string& text) {
  return testing::ExpectInputError([&] { ParseRecording(text, "rec.txt"); }, text);
}

using testing::Contains;

TEST(RecordingReader, WhitespaceSeparatedAsImuTk) {
  const std::vector<Sample> s = ParseRecording(
      "   2.9840000e-02   3.3108000e+04   3.3329000e+04   3.6429000e+04\n"
      "\t3.9857000e-02\t3.3096000e+04 3.3336000e+04   3.6437000e+04",  // no final newline
      "rec.txt");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[0].t_s, 0.02984);
  EXPECT_EQ(s[0].raw_counts, Eigen::Vector3d(33108, 33329, 36429));
  EXPECT_TRUE(std::isnan(s[0].temp_c));
  EXPECT_EQ(s[1].raw_counts, Eigen::Vector3d(33096, 33336, 36437));
}

TEST(RecordingReader, CommaSeparatedWithOrWithoutBlanks) {
  const std::vector<Sample> s =
      ParseRecording("0.0,1,2,3\n0.5, 4 ,+5,\t-6\n1.0 7,8 9\n", "rec.txt");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[1].raw_counts, Eigen::Vector3d(4, 5, -6));
  EXPECT_EQ(s[2].raw_counts, Eigen::Vector3d(7, 8, 9));
}

TEST(RecordingReader, WithTemperature) {
  const std::vector<Sample> s = ParseRecording("0 1 2 3 24.5\n0.01 1 2 3 24.75\n", "rec.txt");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[0].temp_c, 24.5);
  EXPECT_DOUBLE_EQ(s[1].temp_c, 24.75);
}

TEST(RecordingReader, CommentsBlankLinesCrlfAndBom) {
  const std::vector<Sample> s = ParseRecording(
      "\xEF\xBB\xBF# logger v2\r\n\r\n0 1 2 3\r\n   # inline comment line\r\n   \r\n1 4 5 6\r\n",
      "rec.txt");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[1].t_s, 1.0);
  EXPECT_EQ(s[1].raw_counts, Eigen::Vector3d(4, 5, 6));
}

TEST(RecordingReader, EmptyTextGivesNoSamples) {
  EXPECT_TRUE(ParseRecording("", "rec.txt").empty());
  EXPECT_TRUE(ParseRecording("# only a comment\n\n", "rec.txt").empty());
}

TEST(RecordingReader, NotANumberNamesLineColumnAndField) {
  const InputError e = ParseFailure("0 1 2 3\n0.01 1 2x 3\n");
  EXPECT_STREQ(e.what(), "rec.txt:2:8: field 'ay': '2x' is not a number");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 8);
}

TEST(RecordingReader, NonFiniteValueIsAnError) {
  const InputError e = ParseFailure("0 1 nan 3\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 5);
  EXPECT_EQ(e.message(), "field 'ay': 'nan' is not a finite number");
}

TEST(RecordingReader, TooFewFieldsPointsAtTheEndOfTheLine) {
  const InputError e = ParseFailure("0 1 2 3\n1 1 2\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 6);
  EXPECT_EQ(e.message(), "3 fields here, expected t ax ay az [temp_c]");
}

TEST(RecordingReader, TooManyFieldsPointsAtTheExtraField) {
  const InputError e = ParseFailure("0 1 2 3 20 99\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 12);
  EXPECT_TRUE(Contains(e.message(), "too many fields")) << e.what();
}

TEST(RecordingReader, FieldCountMustMatchTheFirstDataLine) {
  const InputError e = ParseFailure("# t ax ay az temp\n0 1 2 3 20\n1 1 2 3\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 8);
  EXPECT_EQ(e.message(), "4 fields here but 5 on line 2, the first data line");
}

TEST(RecordingReader, EmptyFieldBetweenCommas) {
  const InputError e = ParseFailure("0,1,,3\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 5);
  EXPECT_TRUE(Contains(e.message(), "empty field")) << e.what();
}

TEST(RecordingReader, TrailingComma) {
  const InputError e = ParseFailure("0,1,2,3,\n");
  EXPECT_EQ(e.column(), 8);
  EXPECT_TRUE(Contains(e.message(), "empty field")) << e.what();
}

TEST(RecordingReader, RepeatedTimeIsAnError) {
  const InputError e = ParseFailure("0 1 2 3\n0.01 1 2 3\n\n  0.01 1 2 3\n");
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.column(), 3);
  EXPECT_EQ(e.message(),
            "t = 0.01 s does not increase (line 2 has t = 0.01 s); t must be strictly increasing");
}

TEST(RecordingReader, DecreasingTimeIsAnError) {
  const InputError e = ParseFailure("0 1 2 3\n-1 1 2 3\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 1);
  EXPECT_TRUE(Contains(e.message(), "t = -1 s does not increase (line 1 has t = 0 s)"))
      << e.what();
}

TEST(RecordingReader, MissingFileIsAnErrorNamingThePath) {
  try {
    ReadRecordingFile("/nonexistent/rec.txt");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "cannot open '/nonexistent/rec.txt': No such file or directory");
  }
}

TEST(RecordingReader, ImuTkFileLoadsAllSamples) {
  const std::string path = std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/imu_tk/xsens_acc.mat";
  const std::vector<Sample> s = ReadRecordingFile(path);
  ASSERT_EQ(s.size(), 51175u);
  EXPECT_DOUBLE_EQ(s.front().t_s, 0.02984);
  EXPECT_EQ(s.front().raw_counts, Eigen::Vector3d(33108, 33329, 36429));
  EXPECT_NEAR(s.back().t_s, 511.718, 1e-3);
  EXPECT_TRUE(std::isnan(s.back().temp_c));
}

}  // namespace
}  // namespace accelcal::recording_reader_test

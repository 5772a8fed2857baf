#include "accelcal/io/capture_set_reader.h"

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "test_support.h"

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

constexpr char kHeader[] = "capture,kind,t,ax,ay,az\n";

// Parses `text` expecting an InputError; returns it.
InputError ParseFailure(const std::string& text) {
  return testing::ExpectInputError([&] { ParseCaptureSet(text, "set.csv"); }, text);
}

using testing::Contains;

TEST(CaptureSetReader, ReadsCapturesInFileOrder) {
  const CaptureSet set = ParseCaptureSet(
      "# bench session\n"
      "capture,kind,t,ax,ay,az,temp_c\n"
      "1,static,0.00,2051,2013,2934,24.5\n"
      "1,static,0.01,2050,2012,2935,\n"
      "\n"
      "7,static,5.00,3000,2000,2048,25\n",
      "set.csv");
  EXPECT_EQ(set.source_name, "set.csv");
  EXPECT_FALSE(set.adc_range.has_value());
  ASSERT_EQ(set.captures.size(), 2u);
  const Capture& first = set.captures[0];
  EXPECT_EQ(first.id, 1);
  EXPECT_EQ(first.kind, CaptureKind::kStatic);
  EXPECT_TRUE(std::isnan(first.radius_m));
  EXPECT_TRUE(first.used());
  ASSERT_EQ(first.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(first.samples[1].t_s, 0.01);
  EXPECT_EQ(first.samples[0].raw_counts, Eigen::Vector3d(2051, 2013, 2934));
  EXPECT_DOUBLE_EQ(first.samples[0].temp_c, 24.5);
  EXPECT_TRUE(std::isnan(first.samples[1].temp_c));  // empty temp_c
  EXPECT_EQ(set.captures[1].id, 7);
  EXPECT_EQ(set.captures[1].samples.size(), 1u);
}

TEST(CaptureSetReader, ColumnsInAnyOrder) {
  const CaptureSet set = ParseCaptureSet(
      "label, az ,rpm,t,radius_m,ay,kind,ax,capture\n"
      "spin,3,60,1.5,0.25,2,turntable,1,4\n",
      "set.csv");
  ASSERT_EQ(set.captures.size(), 1u);
  const Capture& c = set.captures[0];
  EXPECT_EQ(c.id, 4);
  EXPECT_EQ(c.kind, CaptureKind::kTurntable);
  EXPECT_EQ(c.label, "spin");
  EXPECT_DOUBLE_EQ(c.radius_m, 0.25);
  EXPECT_DOUBLE_EQ(c.rpm, 60.0);
  EXPECT_DOUBLE_EQ(c.samples[0].t_s, 1.5);
  EXPECT_EQ(c.samples[0].raw_counts, Eigen::Vector3d(1, 2, 3));
}

TEST(CaptureSetReader, QuotedLabelWithCommasAndDoubledQuotes) {
  const CaptureSet set = ParseCaptureSet(
      "capture,kind,t,ax,ay,az,label\n"
      "1,static,0,1,2,3,\"z up, on the \"\"granite\"\" plate\"\n"
      "1,static,1,1,2,3, \"z up, on the \"\"granite\"\" plate\" \n"
      "2,static,2,1,2,3,plain label\n",
      "set.csv");
  ASSERT_EQ(set.captures.size(), 2u);
  EXPECT_EQ(set.captures[0].label, "z up, on the \"granite\" plate");
  EXPECT_EQ(set.captures[0].samples.size(), 2u);
  EXPECT_EQ(set.captures[1].label, "plain label");
}

TEST(CaptureSetReader, CrlfLineEndings) {
  const CaptureSet set = ParseCaptureSet(
      "# adc_range_counts = 0,4095\r\ncapture,kind,t,ax,ay,az,label\r\n"
      "1,static,0,1,2,3,a\r\n1,static,1,1,2,3,a\r\n",
      "set.csv");
  ASSERT_EQ(set.captures.size(), 1u);
  EXPECT_EQ(set.captures[0].label, "a");  // no stray '\r'
  EXPECT_EQ(set.captures[0].samples.size(), 2u);
  ASSERT_TRUE(set.adc_range.has_value());
  EXPECT_DOUBLE_EQ(set.adc_range->max_counts, 4095.0);
}

TEST(CaptureSetReader, Utf8ByteOrderMarkIsSkipped) {
  const CaptureSet set =
      ParseCaptureSet("\xEF\xBB\xBF" "capture,kind,t,ax,ay,az\n1,static,0,1,2,3\n", "set.csv");
  ASSERT_EQ(set.captures.size(), 1u);
  EXPECT_EQ(set.captures[0].id, 1);
}

TEST(CaptureSetReader, AdcRangeMetadataToleratesBlanks) {
  const CaptureSet set = ParseCaptureSet(
      "#adc_range_counts=-32768 , 32767\n# adc_range_counts_note: not metadata\n"
      "capture,kind,t,ax,ay,az\n1,static,0,1,2,3\n",
      "set.csv");
  ASSERT_TRUE(set.adc_range.has_value());
  EXPECT_DOUBLE_EQ(set.adc_range->min_counts, -32768.0);
  EXPECT_DOUBLE_EQ(set.adc_range->max_counts, 32767.0);
}

TEST(CaptureSetReader, MalformedAdcRangeIsAnError) {
  const InputError e =
      ParseFailure("#  adc_range_counts = 4095\ncapture,kind,t,ax,ay,az\n1,static,0,1,2,3\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 23);  // the value
  EXPECT_TRUE(Contains(e.message(), "# adc_range_counts = MIN,MAX")) << e.what();
}

TEST(CaptureSetReader, AdcRangeWithMinNotBelowMaxIsAnError) {
  const InputError e =
      ParseFailure("# adc_range_counts = 10,10\ncapture,kind,t,ax,ay,az\n1,static,0,1,2,3\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_TRUE(Contains(e.message(), "MIN < MAX")) << e.what();
}

TEST(CaptureSetReader, AdcRangeGivenTwiceIsAnError) {
  const InputError e = ParseFailure(
      "# adc_range_counts = 0,4095\n# adc_range_counts = 0,1023\ncapture,kind,t,ax,ay,az\n"
      "1,static,0,1,2,3\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 3);
  EXPECT_TRUE(Contains(e.message(), "twice (first on line 1)")) << e.what();
}

TEST(CaptureSetReader, WhatReadsFileLineColumnMessage) {
  const InputError e = ParseFailure(std::string(kHeader) + "1,static,0,abc,2,3\n");
  EXPECT_STREQ(e.what(), "set.csv:2:12: column 'ax': 'abc' is not a number");
}

TEST(CaptureSetReader, NotANumberNamesColumnAndValue) {
  const InputError e = ParseFailure(std::string(kHeader) + "1,static,0,1,2,3\n1,static,0.5,1, 2x ,3\n");
  EXPECT_EQ(e.file(), "set.csv");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 17);
  EXPECT_EQ(e.message(), "column 'ay': '2x' is not a number");
}

TEST(CaptureSetReader, ColumnCountsCharactersNotBytes) {
  // "é" is two bytes in UTF-8 but one column in an editor.
  const InputError e = ParseFailure(
      "label,capture,kind,t,ax,ay,az\n\xC3\xA9,1,static,0,1,oops,3\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 16);
  EXPECT_EQ(e.message(), "column 'ay': 'oops' is not a number");
}

TEST(CaptureSetReader, TooFewFieldsPointsAtTheEndOfTheLine) {
  const InputError e = ParseFailure(std::string(kHeader) + "1,static,0,1,2\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 15);
  EXPECT_TRUE(Contains(e.message(), "wrong number of fields: 5 here, 6 in the header")) << e.what();
}

TEST(CaptureSetReader, TooManyFieldsPointsAtTheFirstExtraField) {
  const InputError e = ParseFailure(std::string(kHeader) + "1,static,0,1,2,3,4\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 18);
  EXPECT_TRUE(Contains(e.message(), "wrong number of fields: 7 here, 6 in the header")) << e.what();
}

TEST(CaptureSetReader, UnterminatedQuote) {
  const InputError e =
      ParseFailure("capture,kind,t,ax,ay,az,label\n1,static,0,1,2,3,\"open, never closed\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 18);
  EXPECT_EQ(e.message(), "unterminated quote");
}

TEST(CaptureSetReader, TextAfterClosingQuote) {
  const InputError e =
      ParseFailure("capture,kind,t,ax,ay,az,label\n1,static,0,1,2,3,\"a\"b\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 21);
  EXPECT_TRUE(Contains(e.message(), "after a closing quote")) << e.what();
}

TEST(CaptureSetReader, EmptyFile) {
  const InputError e = ParseFailure("");
  EXPECT_EQ(e.line(), 0);
  EXPECT_EQ(e.column(), 0);
  EXPECT_TRUE(Contains(e.message(), "no header row")) << e.what();
  EXPECT_TRUE(Contains(e.what(), "set.csv: no header row")) << e.what();
}

TEST(CaptureSetReader, OnlyCommentsMeansNoHeader) {
  const InputError e = ParseFailure("# adc_range_counts = 0,4095\n\n# nothing else\n");
  EXPECT_EQ(e.line(), 0);
  EXPECT_TRUE(Contains(e.message(), "no header row")) << e.what();
}

TEST(CaptureSetReader, HeaderButNoRows) {
  const InputError e = ParseFailure(std::string("# comment\n") + kHeader + "\n# the end\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 0);
  EXPECT_EQ(e.message(), "a header but no data rows");
}

TEST(CaptureSetReader, MissingRequiredColumn) {
  const InputError e = ParseFailure("capture,kind,t,ax,ay\n1,static,0,1,2\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 1);
  EXPECT_TRUE(Contains(e.message(), "lacks the required column 'az'")) << e.what();
}

TEST(CaptureSetReader, UnknownColumnCatchesTypos) {
  const InputError e = ParseFailure("capture,kind,t,ax,ay,az,tmep_c\n1,static,0,1,2,3,20\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 25);
  EXPECT_TRUE(Contains(e.message(), "unknown column 'tmep_c'")) << e.what();
}

TEST(CaptureSetReader, DuplicateColumn) {
  const InputError e = ParseFailure("capture,kind,t,ax,ay,az,ax\n1,static,0,1,2,3,1\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 25);
  EXPECT_EQ(e.message(), "column 'ax' appears twice in the header");
}

TEST(CaptureSetReader, UnknownKind) {
  const InputError e = ParseFailure(std::string(kHeader) + "1,rotating,0,1,2,3\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 3);
  EXPECT_TRUE(Contains(e.message(), "unknown kind 'rotating'")) << e.what();
}

TEST(CaptureSetReader, BadCaptureId) {
  for (const std::string id : {"x1", "1.5", "-2", "99999999999"}) {
    const InputError e = ParseFailure(std::string(kHeader) + id + ",static,0,1,2,3\n");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 1);
    EXPECT_TRUE(Contains(e.message(), "'" + id + "' is not a capture id")) << e.what();
  }
}

TEST(CaptureSetReader, NonContiguousCaptureIdNamesBothLines) {
  const InputError e = ParseFailure(std::string(kHeader) +
                                    "1,static,0,1,2,3\n1,static,1,1,2,3\n"
                                    "2,static,2,1,2,3\n1,static,3,1,2,3\n");
  EXPECT_EQ(e.line(), 5);
  EXPECT_EQ(e.column(), 1);
  EXPECT_TRUE(Contains(e.message(), "capture 1 reappears after capture 2 (which began on line 4)"))
      << e.what();
  EXPECT_TRUE(Contains(e.message(), "lines 2-3")) << e.what();
}

TEST(CaptureSetReader, NonContiguousIdSpanIgnoresCommentsBetweenCaptures) {
  const InputError e = ParseFailure(std::string(kHeader) +
                                    "1,static,0,1,2,3\n# pose 2\n\n2,static,2,1,2,3\n"
                                    "1,static,3,1,2,3\n");
  EXPECT_EQ(e.line(), 6);
  EXPECT_TRUE(Contains(e.message(), "began on line 5); it was on lines 2-2")) << e.what();
}

TEST(CaptureSetReader, TemperatureNanIsUnknownButInfIsAnError) {
  const CaptureSet set = ParseCaptureSet(
      "capture,kind,t,ax,ay,az,temp_c\n1,static,0,1,2,3,nan\n", "set.csv");
  EXPECT_TRUE(std::isnan(set.captures[0].samples[0].temp_c));
  const InputError e = ParseFailure("capture,kind,t,ax,ay,az,temp_c\n1,static,0,1,2,3,-inf\n");
  EXPECT_EQ(e.column(), 18);
  EXPECT_EQ(e.message(), "column 'temp_c': '-inf' is not a finite number");
}

TEST(CaptureSetReader, TurntableRowsCarryRadiusAndRpm) {
  const CaptureSet set = ParseCaptureSet(
      "capture,kind,t,ax,ay,az,radius_m,rpm\n1,static,0,1,2,3,,\n"
      "2,turntable,1,1,2,3,0.15,90\n2,turntable,2,1,2,3,0.15,90\n",
      "set.csv");
  ASSERT_EQ(set.captures.size(), 2u);
  EXPECT_EQ(set.captures[1].kind, CaptureKind::kTurntable);
  EXPECT_DOUBLE_EQ(set.captures[1].radius_m, 0.15);
  EXPECT_DOUBLE_EQ(set.captures[1].rpm, 90.0);
}

TEST(CaptureSetReader, TurntableRowWithoutRadiusColumn) {
  const InputError e =
      ParseFailure("capture,kind,t,ax,ay,az,rpm\n1,turntable,0,1,2,3,60\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 3);  // the kind
  EXPECT_TRUE(Contains(e.message(), "the header has no 'radius_m' column")) << e.what();
}

TEST(CaptureSetReader, TurntableRowWithEmptyRpm) {
  const InputError e =
      ParseFailure("capture,kind,t,ax,ay,az,radius_m,rpm\n1,turntable,0,1,2,3,0.1,\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 25);
  EXPECT_EQ(e.message(), "column 'rpm': a turntable row needs a value (> 0)");
}

TEST(CaptureSetReader, TurntableRowWithNonPositiveRadius) {
  const InputError e =
      ParseFailure("capture,kind,t,ax,ay,az,radius_m,rpm\n1,turntable,0,1,2,3,-0.1,60\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 21);
  EXPECT_EQ(e.message(), "column 'radius_m': -0.1 must be > 0");
}

TEST(CaptureSetReader, TurntableRowWithInfiniteRpm) {
  const InputError e =
      ParseFailure("capture,kind,t,ax,ay,az,radius_m,rpm\n1,turntable,0,1,2,3,0.1,inf\n");
  EXPECT_EQ(e.column(), 25);
  EXPECT_EQ(e.message(), "column 'rpm': 'inf' is not a finite number");
}

TEST(CaptureSetReader, StaticRowWithRadius) {
  const InputError e =
      ParseFailure("capture,kind,t,ax,ay,az,radius_m,rpm\n1,static,0,1,2,3,0.1,\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 18);
  EXPECT_TRUE(Contains(e.message(), "column 'radius_m': must be empty on a static row")) << e.what();
}

TEST(CaptureSetReader, KindMustNotChangeWithinACapture) {
  const InputError e = ParseFailure(
      "capture,kind,t,ax,ay,az,radius_m,rpm\n1,static,0,1,2,3,,\n1,turntable,1,1,2,3,0.1,60\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 3);
  EXPECT_TRUE(Contains(e.message(), "'turntable' differs from 'static' on line 2")) << e.what();
}

TEST(CaptureSetReader, RpmMustNotChangeWithinACapture) {
  const InputError e = ParseFailure(
      "capture,kind,t,ax,ay,az,radius_m,rpm\n3,turntable,0,1,2,3,0.1,60\n"
      "3,turntable,1,1,2,3,0.1,61\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 25);
  EXPECT_TRUE(Contains(e.message(), "column 'rpm': '61' differs from '60' on line 2, the first "
                                    "row of capture 3")) << e.what();
}

TEST(CaptureSetReader, LabelMustNotChangeWithinACapture) {
  const InputError e = ParseFailure(
      "capture,kind,t,ax,ay,az,label\n1,static,0,1,2,3,z up\n1,static,1,1,2,3,z down\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 18);
  EXPECT_TRUE(Contains(e.message(), "column 'label': 'z down' differs from 'z up'")) << e.what();
}

TEST(CaptureSetReader, TimeMustNotDecreaseAcrossTheFile) {
  const InputError e = ParseFailure(std::string(kHeader) +
                                    "1,static,5,1,2,3\n1,static,5,1,2,3\n2,static,4.5,1,2,3\n");
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.column(), 10);
  EXPECT_TRUE(Contains(e.message(), "t = 4.5 s is earlier than t = 5 s on line 3")) << e.what();
}

TEST(CaptureSetReader, TimeMustBeFinite) {
  const InputError e = ParseFailure(std::string(kHeader) + "1,static,nan,1,2,3\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 10);
  EXPECT_EQ(e.message(), "column 't': 'nan' is not a finite number");
}

TEST(CaptureSetReader, NonFiniteReadingsAreDataNotSyntax) {
  const CaptureSet set = ParseCaptureSet(
      std::string(kHeader) + "1,static,0,NaN,2,3\n1,static,1,1,inf,3\n1,static,2,1,2,-Infinity\n",
      "set.csv");
  ASSERT_EQ(set.captures.size(), 1u);
  const std::vector<Sample>& s = set.captures[0].samples;
  ASSERT_EQ(s.size(), 3u);
  EXPECT_TRUE(std::isnan(s[0].raw_counts.x()));
  EXPECT_TRUE(std::isinf(s[1].raw_counts.y()));
  EXPECT_TRUE(std::isinf(s[2].raw_counts.z()) && s[2].raw_counts.z() < 0);
}

TEST(CaptureSetReader, MissingFileIsAnErrorNamingThePath) {
  const std::string path = "/nonexistent/dir/set.csv";
  try {
    ReadCaptureSetFile(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    FAIL() << "an InputError, expected a plain Error: " << e.what();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "cannot open '/nonexistent/dir/set.csv': No such file or directory");
  }
}

TEST(CaptureSetReader, ReadsAFile) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "accelcal_capture_set_reader_test.csv";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("capture,kind,t,ax,ay,az\n1,static,0,1,2,3\n", f);
    std::fclose(f);
  }
  const CaptureSet set = ReadCaptureSetFile(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(set.source_name, path.string());
  ASSERT_EQ(set.captures.size(), 1u);
}

}  // namespace
}  // namespace accelcal

namespace accelcal {
namespace {

TEST(CaptureSetReader, ReadsTheTurntableUpAxis) {
  const CaptureSet set = ParseCaptureSet(
      "capture,kind,t,ax,ay,az,radius_m,rpm,up_axis\n"
      "1,turntable,0,1,2,3,0.1,120,-y\n1,turntable,0.01,1,2,3,0.1,120,-y\n"
      "2,turntable,1,1,2,3,0.1,120,\n", "set.csv");
  ASSERT_EQ(set.captures.size(), 2u);
  ASSERT_TRUE(set.captures[0].up_axis.has_value());
  EXPECT_EQ(*set.captures[0].up_axis, SensorAxis::kMinusY);
  EXPECT_FALSE(set.captures[1].up_axis.has_value());
}

TEST(CaptureSetReader, RefusesABadOrMisplacedUpAxis) {
  InputError e = testing::ExpectInputError(
      [] { ParseCaptureSet("capture,kind,t,ax,ay,az,radius_m,rpm,up_axis\n1,turntable,0,1,2,3,0.1,120,up\n", "s.csv"); },
      "bad axis");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 29);
  EXPECT_NE(std::string(e.what()).find("'up' is not one of +x"), std::string::npos) << e.what();
  e = testing::ExpectInputError(
      [] { ParseCaptureSet("capture,kind,t,ax,ay,az,up_axis\n1,static,0,1,2,3,+z\n", "s.csv"); },
      "static row");
  EXPECT_NE(std::string(e.what()).find("must be empty on a static row"), std::string::npos) << e.what();
  e = testing::ExpectInputError(
      [] {
        ParseCaptureSet("capture,kind,t,ax,ay,az,radius_m,rpm,up_axis\n1,turntable,0,1,2,3,0.1,120,+z\n"
                        "1,turntable,0.1,1,2,3,0.1,120,+x\n", "s.csv");
      },
      "differs");
  EXPECT_NE(std::string(e.what()).find("column 'up_axis': '+x' differs from '+z'"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace accelcal

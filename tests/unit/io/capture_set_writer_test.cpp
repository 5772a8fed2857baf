#include "accelcal/io/capture_set_writer.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/io/csv_fields.h"

namespace accelcal::capture_set_writer_test {
namespace {

Sample At(double t_s, double x, double y, double z, double temp_c = kNaN) {
  Sample s;
  s.t_s = t_s;
  s.raw_counts = {x, y, z};
  s.temp_c = temp_c;
  return s;
}

CaptureSet Example() {
  CaptureSet set;
  Capture a;
  a.id = 1;
  a.kind = CaptureKind::kStatic;
  a.label = "z up";
  a.samples = {At(0.0, 2048, 2040, 2389, 25.0), At(0.01, 2049, 2041.5, 2390, 25.125)};
  Capture b;
  b.id = 2;
  b.kind = CaptureKind::kTurntable;
  b.label = "+x radial, r = 0.1 m";
  b.radius_m = 0.1;
  b.rpm = 120.0;
  b.up_axis = SensorAxis::kMinusY;
  b.samples = {At(30.0, 1500, 2040, 2400)};
  Capture c;
  c.id = 3;
  c.kind = CaptureKind::kStatic;
  c.label = "the \"odd\" one";
  c.samples = {At(1e-7, -12, 0, 4095, 24.5)};
  set.captures = {a, b, c};
  set.adc_range = AdcRange{0.0, 4095.0};
  return set;
}

TEST(CaptureSetWriter, WritesTheDocumentedFormatExactly) {
  std::ostringstream out;
  WriteCaptureSet(out, Example());
  EXPECT_EQ(out.str(),
            "# accelcal capture set\n"
            "# adc_range_counts = 0,4095\n"
            "capture,kind,t,ax,ay,az,temp_c,radius_m,rpm,label,up_axis\n"
            "1,static,0,2048,2040,2389,25,,,z up,\n"
            "1,static,0.01,2049,2041.5,2390,25.125,,,z up,\n"
            "2,turntable,30,1500,2040,2400,,0.1,120,\"+x radial, r = 0.1 m\",-y\n"
            "3,static,1e-07,-12,0,4095,24.5,,,\"the \"\"odd\"\" one\",\n");
}

TEST(CaptureSetWriter, LeavesOutTheAdcRangeWhenUnknown) {
  CaptureSet set = Example();
  set.adc_range.reset();
  std::ostringstream out;
  WriteCaptureSet(out, set);
  EXPECT_EQ(out.str().rfind("# accelcal capture set\ncapture,kind,", 0), 0u) << out.str();
}

TEST(CaptureSetWriter, NumbersRoundTrip) {
  CaptureSet set;
  Capture c;
  c.id = 7;
  c.kind = CaptureKind::kTurntable;
  c.radius_m = 0.1 + 0.2;  // 0.30000000000000004
  c.rpm = 1.0 / 3.0;
  c.samples = {At(123.456789012345, 1.0 / 7.0, -0.0, 1e300, 25.1)};
  set.captures = {c};
  std::ostringstream out;
  WriteCaptureSet(out, set);
  std::istringstream in(out.str());
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  std::getline(in, line);
  std::vector<std::string> fields;
  std::stringstream row(line);
  for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
  ASSERT_EQ(fields.size(), 10u) << line;  // empty label, empty up_axis: no eleventh field
  EXPECT_EQ(std::stod(fields[2]), 123.456789012345);
  EXPECT_EQ(std::stod(fields[3]), 1.0 / 7.0);
  EXPECT_EQ(std::stod(fields[5]), 1e300);
  EXPECT_EQ(std::stod(fields[7]), 0.1 + 0.2);
  EXPECT_EQ(std::stod(fields[8]), 1.0 / 3.0);
}

TEST(CaptureSetWriter, CsvFieldQuotesOnlyWhenNeeded) {
  EXPECT_EQ(CsvQuote("plain label"), "plain label");
  EXPECT_EQ(CsvQuote("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvQuote("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvQuote(""), "");
}

TEST(CaptureSetWriter, RefusesALineBreakInALabel) {
  CaptureSet set = Example();
  set.captures[0].label = "two\nlines";
  std::ostringstream out;
  EXPECT_THROW(WriteCaptureSet(out, set), Error);
}

TEST(CaptureSetWriter, FileErrorsNameThePath) {
  try {
    WriteCaptureSetFile("/nonexistent-dir/out.csv", Example());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/out.csv"), std::string::npos);
  }
}

TEST(CaptureSetWriter, WritesAFile) {
  const std::string path = ::testing::TempDir() + "capture_set_writer_test.csv";
  WriteCaptureSetFile(path, Example());
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::ostringstream expected;
  WriteCaptureSet(expected, Example());
  EXPECT_EQ(text.str(), expected.str());
  std::remove(path.c_str());
}

TEST(RecordingWriter, WritesWhitespaceSeparatedLines) {
  std::ostringstream out;
  WriteRecording(out, {At(0.0, 2048, 2040, 2389, 25.0), At(0.01, 2049, 2041, 2390, 25.5)});
  EXPECT_EQ(out.str(),
            "# accelcal recording: t in s, ax ay az in raw counts, temp_c in degC\n"
            "# t ax ay az temp_c\n"
            "0 2048 2040 2389 25\n"
            "0.01 2049 2041 2390 25.5\n");
}

TEST(RecordingWriter, OmitsTemperatureWhenNoSampleHasOne) {
  std::ostringstream out;
  WriteRecording(out, {At(0.0, 1, 2, 3), At(0.5, 4, 5, 6)});
  EXPECT_EQ(out.str(),
            "# accelcal recording: t in s, ax ay az in raw counts\n"
            "# t ax ay az\n"
            "0 1 2 3\n"
            "0.5 4 5 6\n");
}

// Every value as fmt's shortest form prints it (what the writer wrote value by value before
// issue 18 made it fast): whole numbers, fractions, -0, huge and tiny values, NaN.
TEST(RecordingWriter, WritesEachValueAsItsShortestForm) {
  const double values[] = {0.0, -0.0, 1.0, -1.0, 2052.0, -32768.0, 65535.0, 0.001, 0.1 + 0.2,
                           123456789012345.0, 999999999999999.0, 1e15, -1e15, 1e16, 1e17,
                           4503599627370497.0, 1e-7, 12.5, -3.25e-5, 1.7976931348623157e308, kNaN};
  std::vector<Sample> samples;
  std::string expected_lines;
  double t = 0.0;
  for (double v : values) {
    samples.push_back(At(t, v, -v, v * 3.0, v));
    expected_lines += fmt::format("{} {} {} {} {}\n", t, v, -v, v * 3.0, v);
    t += 0.125;
  }
  std::ostringstream out;
  RecordingWriter writer(out, /*with_temperature=*/true);
  writer.Write(samples);
  writer.Flush();
  const std::string text = out.str();
  const size_t body = text.find("temp_c\n", text.find("# t ")) + 7;
  EXPECT_EQ(text.substr(body), expected_lines);
}

}  // namespace
}  // namespace accelcal::capture_set_writer_test

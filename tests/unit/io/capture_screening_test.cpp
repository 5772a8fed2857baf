#include "accelcal/calibration/capture_screening.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/io/capture_set_reader.h"

namespace accelcal {
namespace {

// A static capture of `n` samples at 100 Hz: mean `level` with noise of a few counts, rounded
// to integer counts as an ADC would.
Capture NoisyCapture(int n, const Eigen::Vector3d& level, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 3.0);
  Capture c;
  c.id = 1;
  for (int i = 0; i < n; ++i) {
    Sample s;
    s.t_s = 0.01 * i;
    s.raw_counts = level + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    s.raw_counts = s.raw_counts.array().round();
    c.samples.push_back(s);
  }
  return c;
}

std::string Reason(const Capture& c, const ScreeningOptions& options = {}) {
  std::vector<Capture> captures = {c};
  ScreenCaptures(captures, options);
  return captures[0].rejection_reason;
}

TEST(CaptureScreening, CleanCaptureIsUsable) {
  ScreeningOptions known;
  known.adc_range = AdcRange{0.0, 4095.0};
  EXPECT_EQ(Reason(NoisyCapture(200, {2048, 2000, 2900})), "");
  EXPECT_EQ(Reason(NoisyCapture(200, {2048, 2000, 2900}), known), "");
  // A signed sensor reading about 0 g on x: noise around 0 counts is not a rail.
  EXPECT_EQ(Reason(NoisyCapture(200, {0, 100, 16000})), "");
}

TEST(CaptureScreening, TooShort) {
  EXPECT_EQ(Reason(NoisyCapture(12, {2048, 2000, 2900})), "12 samples, at least 20 needed");
  ScreeningOptions options;
  options.min_samples = 50;
  EXPECT_EQ(Reason(NoisyCapture(1, {2048, 2000, 2900}), options), "1 sample, at least 50 needed");
}

TEST(CaptureScreening, NonFiniteReadings) {
  Capture c = NoisyCapture(100, {2048, 2000, 2900});
  c.samples[40].t_s = 1.23;  // make the first bad sample's time easy to read
  c.samples[40].raw_counts.x() = kNaN;
  c.samples[41].raw_counts.y() = std::numeric_limits<double>::infinity();
  c.samples[90].raw_counts.z() = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(Reason(c), "3 samples are NaN or infinite (first at t = 1.23 s)");
}

TEST(CaptureScreening, ClippedAtAKnownLimit) {
  Capture c = NoisyCapture(1000, {3900, 2000, 2900});
  for (int i = 0; i < 57; ++i) c.samples[i * 17].raw_counts.x() = 4095;
  ScreeningOptions options;
  options.adc_range = AdcRange{0.0, 4095.0};
  EXPECT_EQ(Reason(c, options), "x clipped at the ADC limit 4095 counts in 57 of 1000 samples");
}

TEST(CaptureScreening, KnownLimitCountsReadingsBeyondIt) {
  Capture c = NoisyCapture(100, {2048, 2000, 2900});
  c.samples[3].raw_counts.y() = -5;  // beyond the lower limit (a sign-extension glitch)
  ScreeningOptions options;
  options.adc_range = AdcRange{0.0, 4095.0};
  EXPECT_EQ(Reason(c, options), "y clipped at the ADC limit 0 counts in 1 of 100 samples");
}

TEST(CaptureScreening, InferredUnsignedRail) {
  Capture c = NoisyCapture(500, {2048, 2000, 65530});
  for (int i = 0; i < 500; i += 10) c.samples[i].raw_counts.z() = 65535;  // 50 = 10%
  for (Sample& s : c.samples) s.raw_counts.z() = std::min(s.raw_counts.z(), 65535.0);
  const std::string reason = Reason(c);
  EXPECT_EQ(reason.rfind("z clipped at 65535 counts (a typical ADC rail; the range is not "
                         "known) in ", 0), 0u) << reason;
  EXPECT_NE(reason.find(" of 500 samples"), std::string::npos) << reason;
}

TEST(CaptureScreening, InferredSignedRailsAtBothEnds) {
  Capture c = NoisyCapture(200, {32760, -32760, 0});
  for (int i = 0; i < 10; ++i) {
    c.samples[i].raw_counts.x() = 32767;
    c.samples[i].raw_counts.y() = -32768;
  }
  for (Sample& s : c.samples) {
    s.raw_counts.x() = std::min(s.raw_counts.x(), 32767.0);
    s.raw_counts.y() = std::max(s.raw_counts.y(), -32768.0);
  }
  const std::string reason = Reason(c);
  EXPECT_NE(reason.find("x clipped at 32767 counts"), std::string::npos) << reason;
  EXPECT_NE(reason.find("y clipped at -32768 counts"), std::string::npos) << reason;
}

TEST(CaptureScreening, InferredRailNeedsTwoPercentOfSamples) {
  Capture c = NoisyCapture(1000, {2048, 2000, 2900});
  for (int i = 0; i < 19; ++i) c.samples[i * 50].raw_counts.x() = 4095;  // 1.9%
  EXPECT_EQ(Reason(c), "");
  c.samples[999].raw_counts.x() = 4095;  // 2.0%
  EXPECT_EQ(Reason(c), "x clipped at 4095 counts (a typical ADC rail; the range is not known) in "
                       "20 of 1000 samples");
}

TEST(CaptureScreening, RepeatedExtremeThatIsNoRailIsNotClipping) {
  Capture c = NoisyCapture(100, {2048, 2000, 2900});
  for (int i = 0; i < 50; ++i) c.samples[i].raw_counts.x() = 4000;  // flat, but not 2^n - 1
  for (Sample& s : c.samples) s.raw_counts.x() = std::min(s.raw_counts.x(), 4000.0);
  EXPECT_EQ(Reason(c), "");
}

TEST(CaptureScreening, AllReasonsAreReported) {
  Capture c = NoisyCapture(10, {2048, 2000, 2900});
  c.samples[2].raw_counts.z() = kNaN;
  ScreeningOptions options;
  options.adc_range = AdcRange{0.0, 4095.0};
  c.samples[5].raw_counts.x() = 4095;
  EXPECT_EQ(Reason(c, options),
            "10 samples, at least 20 needed; 1 sample is NaN or infinite (first at t = 0.02 s); "
            "x clipped at the ADC limit 4095 counts in 1 of 9 samples");
}

TEST(CaptureScreening, ScreeningOverwritesAnOldReason) {
  std::vector<Capture> captures = {NoisyCapture(100, {1, 2, 3})};
  captures[0].rejection_reason = "stale";
  ScreenCaptures(captures, {});
  EXPECT_TRUE(captures[0].used());
}

TEST(CaptureScreening, InvalidOptionsThrow) {
  std::vector<Capture> captures;
  ScreeningOptions options;
  options.min_samples = 1;
  EXPECT_NE(options.Validate(), "");
  EXPECT_THROW(ScreenCaptures(captures, options), Error);
  options = {};
  options.adc_range = AdcRange{10.0, 10.0};
  EXPECT_NE(options.Validate(), "");
  options = {};
  options.rail_fraction = 0.0;
  EXPECT_NE(options.Validate(), "");
  EXPECT_EQ(ScreeningOptions{}.Validate(), "");
}

TEST(CaptureScreening, NanCaptureReadFromAFileIsScreenedOut) {
  std::string text = "# adc_range_counts = 0, 4095\ncapture,kind,t,ax,ay,az,label\n";
  for (int i = 0; i < 30; ++i) text += "1,static," + std::to_string(i * 0.01) + ",2048,2000,2900,ok\n";
  for (int i = 0; i < 30; ++i) {
    const std::string ax = (i == 4 || i == 9) ? "nan" : "2050";
    text += "2,static," + std::to_string(1.0 + i * 0.01) + "," + ax + ",2000,2900,bad\n";
  }
  CaptureSet set = ParseCaptureSet(text, "set.csv");
  ScreeningOptions options;
  options.adc_range = set.adc_range;
  ScreenCaptures(set.captures, options);
  ASSERT_EQ(set.captures.size(), 2u);
  EXPECT_TRUE(set.captures[0].used());
  EXPECT_EQ(set.captures[1].rejection_reason,
            "2 samples are NaN or infinite (first at t = 1.04 s)");
}

}  // namespace
}  // namespace accelcal

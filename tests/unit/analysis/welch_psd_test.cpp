// Welch PSD: white noise of std sigma at fs is flat at 2 sigma^2 / fs (one-sided), and a
// sinusoid of amplitude A lands at its frequency with power A^2 / 2 (Parseval).
#include "accelcal/analysis/welch_psd.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"

namespace accelcal::analysis {
namespace {

std::vector<double> WhiteNoise(long n, double sigma, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> x(static_cast<std::size_t>(n));
  for (double& v : x) v = normal(rng);
  return x;
}

double MeanOver(const PowerSpectrum& p, std::size_t from, std::size_t to) {
  double sum = 0.0;
  for (std::size_t k = from; k < to; ++k) sum += p.density[k];
  return sum / static_cast<double>(to - from);
}

TEST(WelchPsdTest, WhiteNoiseIsFlatAtTwoSigmaSquaredOverRate) {
  const double sigma = 2.0, rate_hz = 100.0;
  const PowerSpectrum p = WelchPsd(WhiteNoise(1 << 16, sigma, 3), rate_hz);
  EXPECT_EQ(p.segment_length, 8192);  // largest power of two with >= 8 segments
  EXPECT_EQ(p.num_segments, 15);
  EXPECT_DOUBLE_EQ(p.resolution_hz, rate_hz / 8192);
  ASSERT_EQ(p.density.size(), 4097u);
  EXPECT_DOUBLE_EQ(p.frequency_hz.back(), 50.0);
  const double expected = 2.0 * sigma * sigma / rate_hz;
  // Each bin averages 15 segments; the mean over ~1000 bins has a relative error of well under
  // 1 % (1 / sqrt(1000 * 15 * ~0.5), the 0.5 for the overlap). 3 % is several of those.
  const std::size_t q = 1024;
  EXPECT_NEAR(MeanOver(p, 4, q) / expected, 1.0, 0.03);           // low quarter
  EXPECT_NEAR(MeanOver(p, 3 * q, 4 * q) / expected, 1.0, 0.03);   // high quarter
}

TEST(WelchPsdTest, SinusoidLandsAtItsFrequencyWithItsPower) {
  const double rate_hz = 100.0;
  const long n = 6000;
  for (double f0 : {12.5, 13.3}) {  // on a bin (L = 1024: 12.5 = 128 bins), and between bins
    const double amplitude = 3.0;
    std::vector<double> x(static_cast<std::size_t>(n));
    for (long i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = amplitude * std::sin(2.0 * M_PI * f0 * i / rate_hz + 0.3);
    const PowerSpectrum p = WelchPsd(x, rate_hz);
    ASSERT_EQ(p.segment_length, 1024);
    std::size_t peak = 0;
    for (std::size_t k = 1; k < p.density.size(); ++k)
      if (p.density[k] > p.density[peak]) peak = k;
    EXPECT_NEAR(p.frequency_hz[peak], f0, p.resolution_hz) << f0;
    // Power in the line: the PSD integrated over the peak (the Hann window spreads it over a
    // few bins), equal to the mean square A^2 / 2.
    double power = 0.0;
    for (std::size_t k = peak - 8; k <= peak + 8; ++k) power += p.density[k] * p.resolution_hz;
    EXPECT_NEAR(power / (0.5 * amplitude * amplitude), 1.0, 0.01) << f0;
  }
}

TEST(WelchPsdTest, ExplicitSegmentLengthAndErrors) {
  const std::vector<double> x = WhiteNoise(1000, 1.0, 5);
  WelchOptions options;
  options.segment_length = 128;
  const PowerSpectrum p = WelchPsd(x, 10.0, options);
  EXPECT_EQ(p.segment_length, 128);
  EXPECT_EQ(p.num_segments, (1000 - 128) / 64 + 1);

  options.segment_length = 100;  // not a power of two
  EXPECT_THROW(WelchPsd(x, 10.0, options), Error);
  EXPECT_THROW(WelchPsd(std::vector<double>(10, 1.0), 10.0), Error);  // too short
  EXPECT_THROW(WelchPsd(x, 0.0), Error);
  std::vector<double> with_nan = x;
  with_nan[7] = std::nan("");
  EXPECT_THROW(WelchPsd(with_nan, 10.0), Error);
}

TEST(WelchPsdTest, TrendIsRemovedPerSegment) {
  // A ramp plus white noise: the detrending leaves the white level in all but the lowest bins.
  std::vector<double> x = WhiteNoise(1 << 14, 1.0, 9);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.01 * static_cast<double>(i);
  const PowerSpectrum p = WelchPsd(x, 100.0);
  EXPECT_NEAR(MeanOver(p, 4, p.density.size() - 1) / (2.0 / 100.0), 1.0, 0.05);
}

}  // namespace
}  // namespace accelcal::analysis

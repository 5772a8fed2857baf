#include "accelcal/analysis/record_analysis.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

// A static record of three axes: white noise of per-sample std sigma (noise density
// N = sigma / sqrt(rate)) on a bias that random-walks with coefficient K (increments of std
// K sqrt(dt)); axis i has sigma_i and K_i scaled by (1 + i/2).
struct SyntheticRecord {
  double rate_hz = 50.0;
  double duration_s = 7200.0;
  double sigma = 1.0;    // unit, per sample
  double k = 0.01;       // unit/sqrt(s)
  std::uint64_t seed = 1;
};

void Feed(const SyntheticRecord& r, RecordAnalyzer& analyzer, double skip_from_s = -1,
          double skip_to_s = -1) {
  std::mt19937_64 rng(r.seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  const double dt = 1.0 / r.rate_hz;
  Eigen::Vector3d bias(2048, 2010, 2500);
  const auto n = static_cast<long>(r.duration_s * r.rate_hz);
  for (long i = 0; i < n; ++i) {
    Eigen::Vector3d value;
    for (int a = 0; a < 3; ++a) {
      bias[a] += (1 + a / 2.0) * r.k * std::sqrt(dt) * unit(rng);
      value[a] = bias[a] + (1 + a / 2.0) * r.sigma * unit(rng);
    }
    const double t = i * dt;
    if (t >= skip_from_s && t < skip_to_s) continue;  // lost: a gap
    analyzer.Add(t, value, kNaN);
  }
}

TEST(RecordAnalysis, RecoversWhiteNoiseAndRandomWalk) {
  int k_within = 0, trials = 0;
  for (std::uint64_t seed : {1, 2, 3}) {
    SyntheticRecord r;
    r.seed = seed;
    RecordAnalyzer analyzer({}, "counts");
    Feed(r, analyzer);
    const RecordAnalysis result = analyzer.Result();
    EXPECT_NEAR(result.rate_hz, r.rate_hz, 1e-9);
    EXPECT_TRUE(result.rate_estimated);
    EXPECT_TRUE(result.gaps.empty());
    for (int a = 0; a < 3; ++a) {
      const double scale = 1 + a / 2.0;
      const AxisAnalysis& axis = result.axes[static_cast<size_t>(a)];
      ASSERT_TRUE(axis.read_offs.has_value());
      const double n_true = scale * r.sigma / std::sqrt(r.rate_hz);
      EXPECT_NEAR(axis.read_offs->noise_density, n_true, 0.10 * n_true) << "axis " << a;
      EXPECT_TRUE(axis.read_offs->white_noise_observed);
      EXPECT_TRUE(axis.read_offs->random_walk_observed);
      ++trials;
      if (std::abs(axis.read_offs->random_walk - scale * r.k) < 0.3 * scale * r.k) ++k_within;
      // Each point's band holds the point.
      for (const AllanPoint& p : axis.curve.points) {
        EXPECT_LE(p.adev_lo, p.adev);
        EXPECT_GE(p.adev_hi, p.adev);
      }
    }
  }
  // The longest taus have few degrees of freedom: K is within 30 % in most, not all, trials.
  EXPECT_GE(k_within, trials - 1);
}

TEST(RecordAnalysis, AGapIsListedAndSpannedByNoTerm) {
  SyntheticRecord r;
  r.duration_s = 1200;
  RecordAnalyzer analyzer({}, "counts");
  Feed(r, analyzer, 400.0, 430.0);  // 30 s lost
  const RecordAnalysis result = analyzer.Result();
  ASSERT_EQ(result.gaps.size(), 1u);
  EXPECT_EQ(result.gaps[0].missing_samples, 30 * 50);
  EXPECT_EQ(result.missing_samples, 30 * 50);
  EXPECT_EQ(result.samples, (1200 - 30) * 50);
  // At tau = 1 sample, a gap-free record of N readings gives N - 1 terms; the gap removes the
  // term that would straddle it (and the missing readings' own).
  const AllanPoint& first = result.axes[0].curve.points.front();
  EXPECT_EQ(first.m, 1);
  EXPECT_EQ(first.num_terms, (1200 - 30) * 50 - 2);
  const double n_true = r.sigma / std::sqrt(r.rate_hz);
  EXPECT_NEAR(result.axes[0].read_offs->noise_density, n_true, 0.1 * n_true);
}

TEST(RecordAnalysis, StatedRateAndRefusals) {
  RecordAnalysisOptions options;
  options.rate_hz = 100.0;
  RecordAnalyzer analyzer(options, "m/s^2");
  EXPECT_TRUE(std::isnan(analyzer.Result().t_first_s));
  analyzer.Add(0.0, Eigen::Vector3d(0, 0, 9.8), 25.0);
  EXPECT_THROW(analyzer.Add(0.0, Eigen::Vector3d(0, 0, 9.8), 25.0), Error);       // t repeats
  EXPECT_THROW(analyzer.Add(0.01, Eigen::Vector3d(NAN, 0, 9.8), 25.0), Error);    // NaN
  EXPECT_THROW(analyzer.Add(1e7, Eigen::Vector3d(0, 0, 9.8), 25.0), Error);       // clock jump
  analyzer.Add(0.01, Eigen::Vector3d(0, 0, 9.8), 25.0);
  const RecordAnalysis r = analyzer.Result();
  EXPECT_EQ(r.samples, 2);
  EXPECT_FALSE(r.rate_estimated);
  EXPECT_TRUE(r.has_temperature);
  EXPECT_FALSE(r.axes[0].read_offs.has_value());  // far too short
  EXPECT_THROW(RecordAnalyzer(options, ""), Error);
  options.gap_factor = 1.0;
  EXPECT_THROW(RecordAnalyzer(options, "counts"), Error);
}

}  // namespace
}  // namespace accelcal

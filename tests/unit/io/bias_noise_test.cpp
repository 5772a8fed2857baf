// The virtual bench's long-term bias noise (sim/bias_noise.h): the random walk's and the
// Gauss-Markov sum's increments have the variances theory gives, the flicker approximation's
// Allan deviation sits at 0.664 B, the bench and the live sim source include it reproducibly,
// and the scenario refuses bad values with their position.
#include "accelcal/acquire/sim/bias_noise.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/acquire/source/sim_source.h"
#include "accelcal/io/scenario_file.h"
#include "test_support.h"

namespace accelcal::sim {
namespace {

// Sample variance (n - 1) of `x`.
double Variance(const std::vector<double>& x) {
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double ss = 0.0;
  for (double v : x) ss += (v - mean) * (v - mean);
  return ss / static_cast<double>(x.size() - 1);
}

// Increments of axis `axis` of the bias over steps of dt_s, n of them.
std::vector<double> Increments(BiasNoise& noise, int axis, double dt_s, int n) {
  std::vector<double> d;
  double previous = noise.Advance(0.0)(axis);
  for (int k = 1; k <= n; ++k) {
    const double b = noise.Advance(k * dt_s)(axis);
    d.push_back(b - previous);
    previous = b;
  }
  return d;
}

// The sample variance of n independent normal values has relative std sqrt(2 / (n - 1)); the
// tolerances below are 5 of those.
double Tolerance(int n) { return 5.0 * std::sqrt(2.0 / (n - 1)); }

TEST(BiasNoiseTest, RandomWalkIncrementHasVarianceKSquaredDt) {
  BiasNoiseSpec spec;
  spec.random_walk_counts_per_sqrt_s = Eigen::Vector3d(0.3, 0.0, 2.0);
  for (double dt_s : {0.01, 5.0}) {
    BiasNoise noise(spec, 42);
    const int n = 100000;
    const std::vector<double> dx = Increments(noise, 0, dt_s, n);
    EXPECT_NEAR(Variance(dx) / (0.09 * dt_s), 1.0, Tolerance(n)) << "dt " << dt_s;
    BiasNoise noise_z(spec, 43);
    const std::vector<double> dz = Increments(noise_z, 2, dt_s, n);
    EXPECT_NEAR(Variance(dz) / (4.0 * dt_s), 1.0, Tolerance(n)) << "dt " << dt_s;
    BiasNoise noise_y(spec, 44);
    EXPECT_EQ(Variance(Increments(noise_y, 1, dt_s, 100)), 0.0);  // K = 0: no walk
  }
}

TEST(BiasNoiseTest, GaussMarkovSumIncrementMatchesTheAutocorrelation) {
  // For independent stationary terms, var(b(t + dt) - b(t)) = sum 2 s_i^2 (1 - exp(-dt / T_i)).
  BiasNoiseSpec spec;
  spec.instability_counts = Eigen::Vector3d(0.8, 0.0, 0.0);
  spec.instability_tau_min_s = 0.05;
  spec.instability_tau_max_s = 5.0;
  const std::vector<GaussMarkovTerm> terms = FlickerTerms(0.8, 0.05, 5.0);
  ASSERT_EQ(terms.size(), 5u);  // two per decade, both ends included
  for (double dt_s : {0.01, 1.0}) {
    double expected = 0.0;
    for (const GaussMarkovTerm& t : terms)
      expected += 2.0 * t.sigma * t.sigma * (1.0 - std::exp(-dt_s / t.tau_s));
    BiasNoise noise(spec, 7);
    const int n = 100000;
    // Successive increments of a Gauss-Markov process are slightly correlated, so allow
    // twice the tolerance of independent values.
    EXPECT_NEAR(Variance(Increments(noise, 0, dt_s, n)) / expected, 1.0, 2.0 * Tolerance(n))
        << "dt " << dt_s;
  }
}

TEST(BiasNoiseTest, FlickerApproximationHasTheIeee952AllanFloor) {
  // Closed-form Allan deviation of the sum (independent terms add in variance) against
  // B sqrt(2 ln 2 / pi) (IEEE Std 952-1997 C.1.4).
  const double b = 2.0;
  const std::vector<GaussMarkovTerm> terms = FlickerTerms(b, 1.0, 1000.0);
  const double floor = b * std::sqrt(2.0 * std::log(2.0) / M_PI);
  EXPECT_NEAR(floor / b, 0.664, 0.001);
  for (double tau_s = 3.0; tau_s <= 1000.0; tau_s *= 1.3) {
    double avar = 0.0;
    for (const GaussMarkovTerm& t : terms) avar += GaussMarkovAllanVariance(t, tau_s);
    const double ratio = std::sqrt(avar) / floor;
    const bool inner = tau_s >= 10.0 && tau_s <= 1000.0 / 3.0;
    EXPECT_NEAR(ratio, 1.0, inner ? 0.05 : 0.15) << "tau " << tau_s;
  }
}

TEST(BiasNoiseTest, OffDrawsNothingAndGivesZero) {
  BiasNoise noise(BiasNoiseSpec{}, 1);
  EXPECT_EQ(noise.Advance(0.0), Eigen::Vector3d::Zero());
  EXPECT_EQ(noise.Advance(100.0), Eigen::Vector3d::Zero());
}

Scenario DriftDemo() {
  return LoadScenario(std::string(ACCELCAL_SOURCE_DIR) + "/scenarios/drift_demo.toml");
}

TEST(BiasNoiseTest, BenchIsReproducibleBySeedAndIncludesTheNoise) {
  const Scenario scenario = DriftDemo();
  EXPECT_DOUBLE_EQ(scenario.sensor.bias_noise.random_walk_counts_per_sqrt_s(2), 0.05);
  EXPECT_DOUBLE_EQ(scenario.sensor.bias_noise.instability_counts(0), 0.5);
  VirtualBench a(scenario);
  VirtualBench b(scenario);
  const std::vector<Capture> first = a.SimulateCaptureSet();
  const std::vector<Capture> again = a.SimulateCaptureSet();  // reseeded: the same again
  const std::vector<Capture> other = b.SimulateCaptureSet();
  ASSERT_EQ(first.size(), 1u);
  ASSERT_EQ(first[0].samples.size(), 6000u);
  for (std::size_t k = 0; k < first[0].samples.size(); ++k) {
    ASSERT_EQ(first[0].samples[k].raw_counts, again[0].samples[k].raw_counts) << k;
    ASSERT_EQ(first[0].samples[k].raw_counts, other[0].samples[k].raw_counts) << k;
  }
  // Without the bias noise the white noise stream is the same, so the difference of the two
  // records is the bias noise alone (up to rounding): not zero, and slowly varying.
  Scenario quiet = scenario;
  quiet.sensor.bias_noise = BiasNoiseSpec{};
  const std::vector<Capture> white = VirtualBench(quiet).SimulateCaptureSet();
  double max_abs_diff = 0.0;
  for (std::size_t k = 0; k < white[0].samples.size(); ++k)
    max_abs_diff = std::max(max_abs_diff, (first[0].samples[k].raw_counts -
                                           white[0].samples[k].raw_counts).cwiseAbs().maxCoeff());
  EXPECT_GT(max_abs_diff, 0.0);

  Scenario reseeded = scenario;
  reseeded.bench.seed += 1;
  const std::vector<Capture> different = VirtualBench(reseeded).SimulateCaptureSet();
  EXPECT_NE(first[0].samples[100].raw_counts, different[0].samples[100].raw_counts);
}

TEST(BiasNoiseTest, LiveSimSourceIncludesTheRandomWalk) {
  // A still sensor with only a random walk (K = 2 counts/sqrt(s)) and no white noise: the
  // difference of readings 0.1 s apart has variance K^2 0.1 plus that of two independent
  // rounding errors, 2 / 12 counts^2 (uniform quantization error).
  Scenario scenario = DriftDemo();
  scenario.sensor.noise_counts.setZero();
  scenario.sensor.bias_noise = BiasNoiseSpec{};
  scenario.sensor.bias_noise.random_walk_counts_per_sqrt_s = Eigen::Vector3d(2.0, 2.0, 2.0);
  SimOptions options;
  options.speed = 0.0;
  options.bump_probability = 0.0;
  SimSource source(scenario, options);
  std::vector<Sample> samples;
  while (source.now_s() < 400.0) source.Read(1.0, &samples);
  std::vector<double> dz;
  for (std::size_t k = 10; k < samples.size(); k += 10)
    dz.push_back(samples[k].raw_counts.z() - samples[k - 10].raw_counts.z());
  const int n = static_cast<int>(dz.size());
  EXPECT_GT(n, 3900);
  EXPECT_NEAR(Variance(dz) / (4.0 * 0.1 + 2.0 / 12.0), 1.0, Tolerance(n));
}

const std::string kMinimal = R"([sensor]
bias_counts = [2048, 2048, 2048]
scale_counts_per_mps2 = [34.8, 34.8, 34.8]
noise_counts = [1, 1, 1]
bias_random_walk_counts_per_sqrt_s = [0.05, 0.05, 0.05]
bias_instability_counts = [0.5, 0.5, 0.5]
bias_instability_tau_min_s = 1
bias_instability_tau_max_s = 1000

[adc]
bits = 12

[[capture]]
kind = "static"
label = "z up"
up = [0, 0, 1]
)";

InputError ParseFailsWith(const std::string& from, const std::string& to) {
  std::string text = kMinimal;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  return testing::ExpectInputError([&] { ParseScenario(text, "noise.toml"); }, text);
}

TEST(BiasNoiseTest, ScenarioRefusesNegativeValuesWithFileAndLine) {
  EXPECT_NO_THROW(ParseScenario(kMinimal, "noise.toml"));
  const InputError walk = ParseFailsWith("[0.05, 0.05, 0.05]", "[0.05, -0.05, 0.05]");
  EXPECT_EQ(walk.file(), "noise.toml");
  EXPECT_EQ(walk.line(), 5);
  EXPECT_TRUE(testing::Contains(walk.what(), "bias_random_walk_counts_per_sqrt_s")) << walk.what();
  const InputError instability = ParseFailsWith("[0.5, 0.5, 0.5]", "[0.5, 0.5, -1]");
  EXPECT_EQ(instability.line(), 6);
  const InputError tau = ParseFailsWith("tau_min_s = 1", "tau_min_s = -1");
  EXPECT_EQ(tau.line(), 7);
  const InputError order = ParseFailsWith("tau_max_s = 1000", "tau_max_s = 0.5");
  EXPECT_EQ(order.line(), 8);
  EXPECT_TRUE(testing::Contains(order.what(), "must exceed")) << order.what();
}

}  // namespace
}  // namespace accelcal::sim

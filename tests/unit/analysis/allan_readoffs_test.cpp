#include "accelcal/analysis/allan_readoffs.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

// The Allan deviation of white noise N, flicker B and random walk K (IEEE 952 Table C.1).
double ModelAdev(double n, double b, double k, double tau_s) {
  const double flicker = 0.664 * b;
  return std::sqrt(n * n / tau_s + flicker * flicker + k * k * tau_s / 3.0);
}

std::vector<double> LogTaus(double from_s, double to_s, int per_decade) {
  std::vector<double> taus;
  for (double tau = from_s; tau <= to_s * 1.0001; tau *= std::pow(10.0, 1.0 / per_decade))
    taus.push_back(tau);
  return taus;
}

TEST(AllanReadOffs, ExactCurveGivesItsCoefficients) {
  const double n = 2e-3, b = 5e-5, k = 4e-5;
  const std::vector<double> taus = LogTaus(0.01, 20000, 10);
  std::vector<double> adev, edf;
  for (const double tau : taus) {
    adev.push_back(ModelAdev(n, b, k, tau));
    edf.push_back(80000.0 / tau);  // ~ the independent averages of a 22-hour record
  }
  const AllanReadOffs r = ReadOffAllan(taus, adev, edf);
  // The regions' edges hold some of the neighbouring terms: a few % at most, by the weights.
  EXPECT_NEAR(r.noise_density, n, 0.02 * n);
  EXPECT_NEAR(r.random_walk, k, 0.10 * k);
  EXPECT_TRUE(r.white_noise_observed);
  EXPECT_TRUE(r.random_walk_observed);
  EXPECT_TRUE(r.minimum_is_interior);
  // The flat minimum also holds the white and random-walk terms at their crossing: the minimum
  // of N^2/tau + K^2 tau/3 is 2 N K / sqrt(3), so B read off is sqrt(B^2 + that/0.664^2).
  const double expected_b = std::sqrt(b * b + 2 * n * k / std::sqrt(3.0) / (0.664 * 0.664));
  EXPECT_NEAR(r.bias_instability, expected_b, 0.01 * expected_b);
  EXPECT_NEAR(r.bias_instability_tau_s, std::sqrt(3.0) * n / k, 0.15 * std::sqrt(3.0) * n / k);
  EXPECT_TRUE(r.notes.empty());
}

TEST(AllanReadOffs, NoisyCurveWeightedByEdf) {
  // Each point scattered by its own statistical uncertainty, ~1/sqrt(2 edf) relative, with the
  // few-term long taus much noisier, as in a real record of 12 h.
  const double n = 1e-2, b = 0.0, k = 2e-4;
  const double record_s = 43200;
  const std::vector<double> taus = LogTaus(0.01, record_s / 4, 10);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  int trials_within = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> adev, edf;
    for (const double tau : taus) {
      const double e = std::max(1.0, record_s / tau);  // ~ number of independent averages
      edf.push_back(e);
      adev.push_back(ModelAdev(n, b, k, tau) * (1.0 + unit(rng) / std::sqrt(2.0 * e)));
    }
    const AllanReadOffs r = ReadOffAllan(taus, adev, edf);
    EXPECT_NEAR(r.noise_density, n, 0.02 * n);
    if (std::abs(r.random_walk - k) < 0.3 * k) ++trials_within;
  }
  EXPECT_GE(trials_within, 17);
}

// Allan variance of a first-order Gauss-Markov process of variance s2 and correlation time T:
// (2 s2 T^2 / tau^2)(tau/T - 3/2 + 2 e^(-tau/T) - e^(-2 tau/T) / 2); it grows like a random
// walk (2 s2 / T) tau / 3 below T and falls like white noise 2 s2 T / tau above.
double GaussMarkovAvar(double s2, double t_s, double tau_s) {
  const double x = tau_s / t_s;
  return 2 * s2 * t_s * t_s / (tau_s * tau_s) * (x - 1.5 + 2 * std::exp(-x) - 0.5 * std::exp(-2 * x));
}

TEST(AllanReadOffs, FlickerMadeOfGaussMarkovTermsDoesNotBiasTheLines) {
  // The virtual bench's long-term noise (sim/bias_noise.h): white N, flicker B as Gauss-Markov
  // terms two per decade from 1 to 1000 s (variance B^2 ln(r) / pi each, r = sqrt(10)), and a
  // random walk K, over a 4-hour record at 100 Hz. Its flicker is not flat where it meets the
  // other terms (a global three-term fit read K three times too large here).
  const double n = 0.15, b = 0.5, k = 0.05, record_s = 14400;
  const std::vector<double> taus = LogTaus(0.01, record_s / 4, 10);
  std::vector<double> adev, edf;
  for (const double tau : taus) {
    double avar = n * n / tau + k * k * tau / 3;
    for (double t = 1.0; t <= 1000.0 * 1.0001; t *= std::sqrt(10.0))
      avar += GaussMarkovAvar(b * b * std::log(std::sqrt(10.0)) / M_PI, t, tau);
    adev.push_back(std::sqrt(avar));
    edf.push_back(record_s / tau);
  }
  const AllanReadOffs r = ReadOffAllan(taus, adev, edf);
  EXPECT_NEAR(r.noise_density, n, 0.05 * n);
  EXPECT_NEAR(r.random_walk, k, 0.30 * k);
  EXPECT_TRUE(r.random_walk_observed);
  EXPECT_TRUE(r.minimum_is_interior);
  EXPECT_NEAR(r.bias_instability, b, 0.5 * b);  // the floor also holds white and walk
}

TEST(AllanReadOffs, WhiteOnlySaysRandomWalkIsNotSeen) {
  const std::vector<double> taus = LogTaus(0.01, 100, 10);
  std::vector<double> adev;
  for (const double tau : taus) adev.push_back(ModelAdev(3e-3, 0, 0, tau));
  const AllanReadOffs r = ReadOffAllan(taus, adev, {});
  EXPECT_NEAR(r.noise_density, 3e-3, 1e-9);
  EXPECT_FALSE(r.random_walk_observed);
  EXPECT_FALSE(r.minimum_is_interior);  // still falling at the longest tau
  EXPECT_EQ(r.notes.size(), 2u);        // no random-walk region; B is an upper bound
}

TEST(AllanReadOffs, RefusesMalformedCurves) {
  EXPECT_THROW(ReadOffAllan({1, 2}, {1, 2}, {}), Error);
  EXPECT_THROW(ReadOffAllan({1, 2, 4}, {1, 2}, {}), Error);
  EXPECT_THROW(ReadOffAllan({1, 2, 4}, {1, 2, 3}, {1, 1}), Error);
  EXPECT_THROW(ReadOffAllan({1, 2, 2}, {1, 2, 3}, {}), Error);
  EXPECT_THROW(ReadOffAllan({1, 2, 4}, {1, -2, 3}, {}), Error);
  EXPECT_THROW(ReadOffAllan({1, 2, 4}, {1, NAN, 3}, {}), Error);
  EXPECT_THROW(ReadOffAllan({1, 2, 4}, {1, 2, 3}, {1, 0, 1}), Error);
}

}  // namespace
}  // namespace accelcal

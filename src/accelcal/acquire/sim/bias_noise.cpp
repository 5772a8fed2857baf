#include "accelcal/acquire/sim/bias_noise.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace accelcal::sim {
namespace {

constexpr double kTermsPerDecade = 2.0;

}  // namespace

std::vector<GaussMarkovTerm> FlickerTerms(double b_counts, double tau_min_s, double tau_max_s) {
  std::vector<GaussMarkovTerm> terms;
  if (b_counts == 0.0) return terms;
  const double decades = std::log10(tau_max_s / tau_min_s);
  const int n = std::max(2, static_cast<int>(std::ceil(decades * kTermsPerDecade)) + 1);
  const double log_ratio = std::log(tau_max_s / tau_min_s) / (n - 1);  // ln r
  const double sigma = b_counts * std::sqrt(log_ratio / M_PI);          // s^2 = B^2 ln(r) / pi
  for (int i = 0; i < n; ++i) terms.push_back({sigma, tau_min_s * std::exp(log_ratio * i)});
  return terms;
}

double GaussMarkovAllanVariance(const GaussMarkovTerm& term, double tau_s) {
  const double t = term.tau_s;
  const double x = tau_s / t;
  return 2.0 * term.sigma * term.sigma * t / tau_s *
         (1.0 - (3.0 - 4.0 * std::exp(-x) + std::exp(-2.0 * x)) / (2.0 * x));
}

std::string BiasNoiseSpec::Validate() const {
  if (!random_walk_counts_per_sqrt_s.allFinite() || (random_walk_counts_per_sqrt_s.array() < 0).any())
    return "bias random walk must be finite and not negative";
  if (!instability_counts.allFinite() || (instability_counts.array() < 0).any())
    return "bias instability must be finite and not negative";
  if (!(instability_tau_min_s > 0.0) || !(instability_tau_max_s > instability_tau_min_s) ||
      !std::isfinite(instability_tau_max_s))
    return "bias instability correlation times must satisfy 0 < min < max";
  return "";
}

BiasNoise::BiasNoise(const BiasNoiseSpec& spec, std::uint64_t seed) : spec_(spec), rng_(seed) {
  for (int i = 0; i < 3; ++i) {
    terms_[i] = FlickerTerms(spec_.instability_counts(i), spec_.instability_tau_min_s,
                             spec_.instability_tau_max_s);
  }
}

void BiasNoise::Reset(std::uint64_t seed) {
  rng_.seed(seed);
  unit_.reset();
  started_ = false;
  cached_dt_s_ = -1.0;
}

void BiasNoise::Initialize(double t_s) {
  for (int i = 0; i < 3; ++i) {
    state_[i].assign(terms_[i].size(), 0.0);
    for (std::size_t j = 0; j < terms_[i].size(); ++j) state_[i][j] = terms_[i][j].sigma * unit_(rng_);
    decay_[i].assign(terms_[i].size(), 0.0);
    innovation_[i].assign(terms_[i].size(), 0.0);
  }
  walk_counts_.setZero();
  last_t_s_ = t_s;
  started_ = true;
}

Eigen::Vector3d BiasNoise::Advance(double t_s) {
  if (spec_.IsOff()) return Eigen::Vector3d::Zero();
  if (!started_) Initialize(t_s);
  const double dt_s = std::max(0.0, t_s - last_t_s_);
  last_t_s_ = std::max(last_t_s_, t_s);
  if (dt_s != cached_dt_s_) {
    for (int i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < terms_[i].size(); ++j) {
        const double a = std::exp(-dt_s / terms_[i][j].tau_s);
        decay_[i][j] = a;
        innovation_[i][j] = terms_[i][j].sigma * std::sqrt(1.0 - a * a);
      }
    }
    cached_dt_s_ = dt_s;
  }
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();
  const double sqrt_dt = std::sqrt(dt_s);
  for (int i = 0; i < 3; ++i) {
    const double k = spec_.random_walk_counts_per_sqrt_s(i);
    if (k > 0.0 && dt_s > 0.0) walk_counts_(i) += k * sqrt_dt * unit_(rng_);
    bias(i) = walk_counts_(i);
    for (std::size_t j = 0; j < terms_[i].size(); ++j) {
      if (dt_s > 0.0) state_[i][j] = decay_[i][j] * state_[i][j] + innovation_[i][j] * unit_(rng_);
      bias(i) += state_[i][j];
    }
  }
  return bias;
}

}  // namespace accelcal::sim

// Long-term bias noise of the simulated sensor, per axis, added to every reading on top of the
// white noise (SensorSpec::noise_counts). Two terms, both off by default:
//
//   bias random walk   K, counts/sqrt(s): the bias performs a Wiener process; its increment over
//                      dt is normal with std K sqrt(dt). Allan deviation K sqrt(tau / 3)
//                      (IEEE Std 952-1997 Annex C, C.1.3 "rate random walk"; IEEE Std 1293-1998
//                      Annex, the same term for accelerometers).
//   bias instability   B, counts: flicker (1/f) bias noise, whose Allan deviation is the floor
//                      B sqrt(2 ln 2 / pi) ~= 0.664 B (IEEE Std 952-1997 C.1.4). Flicker noise
//                      has no finite-state generator; it is approximated, as is usual, by a sum
//                      of independent first-order Gauss-Markov processes whose correlation times
//                      are log-spaced (two per decade) over [tau_min_s, tau_max_s], each with
//                      the same variance s^2 = B^2 ln(r) / pi (r the ratio of neighbouring
//                      correlation times). Why: a Gauss-Markov term of variance s^2 and
//                      correlation time T has the two-sided PSD 2 s^2 T / (1 + (2 pi f T)^2);
//                      summed over corner frequencies spaced ln(r) apart in log f this
//                      approaches s^2 / (2 ln(r) f), which equals the flicker PSD B^2 / (2 pi f)
//                      of IEEE 952 for the s^2 above (the construction of Keshner, Proc. IEEE
//                      70(3) 1982, "1/f noise"). The Allan deviation then sits within 5 % of
//                      0.664 B for tau from 10 tau_min_s to tau_max_s / 3, within 15 % from
//                      3 tau_min_s to tau_max_s
//                      (tests/unit/io/bias_noise_test.cpp checks it with the closed-form Allan
//                      variance of a Gauss-Markov process, IEEE 952 C.1.6).
//
// Each Gauss-Markov term is advanced exactly over any step dt: x <- a x + s sqrt(1 - a^2) w with
// a = exp(-dt / T), w ~ N(0, 1) (no Euler error, any sample rate, any gap between captures).
// The terms start from their stationary distribution, the random walk from 0, at the first
// Advance. Cost: O(1) per call (3 x (1 + number of terms) normal draws at most; axes whose K and
// B are zero draw nothing).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace accelcal::sim {

// One first-order Gauss-Markov term: stationary std and correlation time.
struct GaussMarkovTerm {
  double sigma = 0.0;   // stationary standard deviation, counts
  double tau_s = 1.0;   // correlation time, s
};

// The Gauss-Markov terms approximating flicker bias noise of instability `b_counts` over
// correlation times [tau_min_s, tau_max_s] (see above). Empty when b_counts is 0.
// Requires 0 < tau_min_s < tau_max_s.
std::vector<GaussMarkovTerm> FlickerTerms(double b_counts, double tau_min_s, double tau_max_s);

// Closed-form Allan variance of one Gauss-Markov term at averaging time tau_s, counts^2
// (IEEE Std 952-1997 C.1.6): (2 s^2 T / tau) [1 - T / (2 tau) (3 - 4 e^(-tau/T) + e^(-2 tau/T))].
double GaussMarkovAllanVariance(const GaussMarkovTerm& term, double tau_s);

struct BiasNoiseSpec {
  Eigen::Vector3d random_walk_counts_per_sqrt_s = Eigen::Vector3d::Zero();  // K per axis
  Eigen::Vector3d instability_counts = Eigen::Vector3d::Zero();             // B per axis
  double instability_tau_min_s = 1.0;     // shortest Gauss-Markov correlation time, s
  double instability_tau_max_s = 1000.0;  // longest, s

  bool IsOff() const {
    return random_walk_counts_per_sqrt_s.isZero() && instability_counts.isZero();
  }
  // Empty when valid (K, B >= 0 and finite; 0 < tau_min < tau_max), else the problem.
  std::string Validate() const;
};

class BiasNoise {
 public:
  // `spec` must be valid (Validate()).
  BiasNoise(const BiasNoiseSpec& spec, std::uint64_t seed);

  // The bias offset at time t_s, counts, after advancing the processes from the previous call's
  // time (the first call initializes them). A t_s earlier than the previous one does not
  // advance them (dt taken as 0). Zero when the spec is off (no random numbers drawn).
  Eigen::Vector3d Advance(double t_s);

  // Back to the initial state, with a new random stream.
  void Reset(std::uint64_t seed);

 private:
  void Initialize(double t_s);

  BiasNoiseSpec spec_;
  std::vector<GaussMarkovTerm> terms_[3];
  std::vector<double> state_[3];  // Gauss-Markov values, counts
  Eigen::Vector3d walk_counts_ = Eigen::Vector3d::Zero();
  std::mt19937_64 rng_;
  std::normal_distribution<double> unit_;
  bool started_ = false;
  double last_t_s_ = 0.0;
  // exp(-dt / T) per term, cached for the last dt (the common case: a constant sample rate).
  double cached_dt_s_ = -1.0;
  std::vector<double> decay_[3];
  std::vector<double> innovation_[3];  // s sqrt(1 - decay^2)
};

}  // namespace accelcal::sim

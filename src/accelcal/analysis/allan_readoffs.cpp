#include "accelcal/analysis/allan_readoffs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <fmt/core.h>

#include "accelcal/error.h"

namespace accelcal {
namespace {

// sqrt(2 ln 2 / pi): the Allan deviation of flicker noise relative to its coefficient B
// (IEEE Std 952-1997, Table C.1).
constexpr double kFlickerFloor = 0.664;
constexpr int kTerms = 3;  // N^2 / tau, C, K^2 tau / 3

double Basis(int term, double tau_s) {
  switch (term) {
    case 0: return 1.0 / tau_s;
    case 1: return 1.0;
    default: return tau_s / 3.0;
  }
}

void CheckInput(const std::vector<double>& tau_s, const std::vector<double>& adev,
                const std::vector<double>& edf) {
  if (tau_s.size() != adev.size() || (!edf.empty() && edf.size() != tau_s.size()))
    throw Error(fmt::format("Allan read-offs: {} taus, {} deviations and {} edf values",
                            tau_s.size(), adev.size(), edf.size()));
  if (tau_s.size() < 3)
    throw Error(fmt::format("Allan read-offs need at least 3 points of the curve, got {}",
                            tau_s.size()));
  for (size_t i = 0; i < tau_s.size(); ++i) {
    const double w = edf.empty() ? 1.0 : edf[i];
    if (!(tau_s[i] > 0 && adev[i] > 0 && w > 0) || !std::isfinite(tau_s[i]) ||
        !std::isfinite(adev[i]) || !std::isfinite(w))
      throw Error(fmt::format("Allan read-offs: point {} (tau {} s, adev {}, edf {}) is not a "
                              "positive finite number", i, tau_s[i], adev[i], w));
    if (i > 0 && !(tau_s[i] > tau_s[i - 1]))
      throw Error(fmt::format("Allan read-offs: tau must increase (point {})", i));
  }
}

// Weighted least squares of avar against the chosen subset of terms (bit i of `mask` set: term
// i used); false when a coefficient comes out negative or the system is singular.
bool FitSubset(const std::vector<double>& tau_s, const std::vector<double>& avar,
               const std::vector<double>& weight, unsigned mask, std::array<double, kTerms>* c,
               double* cost) {
  std::vector<int> terms;
  for (int k = 0; k < kTerms; ++k)
    if (mask & (1u << k)) terms.push_back(k);
  const auto n = static_cast<Eigen::Index>(tau_s.size());
  const auto p = static_cast<Eigen::Index>(terms.size());
  Eigen::MatrixXd a(n, p);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double sw = std::sqrt(weight[static_cast<size_t>(i)]);
    for (Eigen::Index j = 0; j < p; ++j)
      a(i, j) = sw * Basis(terms[static_cast<size_t>(j)], tau_s[static_cast<size_t>(i)]);
    b(i) = sw * avar[static_cast<size_t>(i)];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < p) return false;
  const Eigen::VectorXd x = qr.solve(b);
  if ((x.array() < 0.0).any()) return false;
  c->fill(0.0);
  for (Eigen::Index j = 0; j < p; ++j) (*c)[static_cast<size_t>(terms[static_cast<size_t>(j)])] = x(j);
  *cost = (a * x - b).squaredNorm();
  return true;
}

// Non-negative least squares over three terms: the best of the feasible subsets.
std::array<double, kTerms> FitNonNegative(const std::vector<double>& tau_s,
                                          const std::vector<double>& avar,
                                          const std::vector<double>& weight) {
  std::array<double, kTerms> best{};
  double best_cost = std::numeric_limits<double>::infinity();
  for (unsigned mask = 1; mask < (1u << kTerms); ++mask) {
    std::array<double, kTerms> c{};
    double cost = 0.0;
    if (FitSubset(tau_s, avar, weight, mask, &c, &cost) && cost < best_cost) {
      best = c;
      best_cost = cost;
    }
  }
  return best;
}

double Model(const std::array<double, kTerms>& c, double tau_s) {
  double v = 0.0;
  for (int k = 0; k < kTerms; ++k) v += c[static_cast<size_t>(k)] * Basis(k, tau_s);
  return v;
}

// Term `k` is the largest of the three at some tau of the curve.
bool Dominates(const std::array<double, kTerms>& c, int k, const std::vector<double>& tau_s) {
  for (const double tau : tau_s) {
    const double mine = c[static_cast<size_t>(k)] * Basis(k, tau);
    bool largest = mine > 0.0;
    for (int j = 0; j < kTerms && largest; ++j)
      if (j != k && c[static_cast<size_t>(j)] * Basis(j, tau) >= mine) largest = false;
    if (largest) return true;
  }
  return false;
}

}  // namespace

AllanReadOffs ReadOffAllan(const std::vector<double>& tau_s, const std::vector<double>& adev,
                           const std::vector<double>& edf) {
  CheckInput(tau_s, adev, edf);
  const size_t n = tau_s.size();
  std::vector<double> avar(n), weight(n);
  for (size_t i = 0; i < n; ++i) avar[i] = adev[i] * adev[i];

  // Var(avar estimate) ~ 2 avar^2 / edf: weights edf / avar^2, with avar first the measured
  // value, then (twice) the fitted model, so a point that happens to fall low is not favoured.
  std::array<double, kTerms> c{};
  for (int pass = 0; pass < 3; ++pass) {
    for (size_t i = 0; i < n; ++i) {
      const double level = pass == 0 ? avar[i] : std::max(Model(c, tau_s[i]), 1e-300);
      weight[i] = (edf.empty() ? 1.0 : edf[i]) / (level * level);
    }
    c = FitNonNegative(tau_s, avar, weight);
  }

  AllanReadOffs r;
  r.noise_density = std::sqrt(c[0]);
  r.random_walk = std::sqrt(c[2]);
  r.white_noise_observed = Dominates(c, 0, tau_s);
  r.random_walk_observed = Dominates(c, 2, tau_s);
  const size_t at_min = static_cast<size_t>(std::min_element(adev.begin(), adev.end()) - adev.begin());
  r.bias_instability = adev[at_min] / kFlickerFloor;
  r.bias_instability_tau_s = tau_s[at_min];
  r.minimum_is_interior = at_min + 1 < n && at_min > 0;

  if (!r.white_noise_observed)
    r.notes.push_back(fmt::format("no white-noise (slope -1/2) region from tau {:.3g} s: the noise "
                                  "density is an upper bound", tau_s.front()));
  if (!r.random_walk_observed)
    r.notes.push_back(fmt::format("no random-walk (slope +1/2) region up to tau {:.3g} s: the "
                                  "random walk is an upper bound; a longer record would show it",
                                  tau_s.back()));
  if (!r.minimum_is_interior)
    r.notes.push_back(at_min == 0 ? "the curve's minimum is its first point: the bias "
                                    "instability is an upper bound"
                                  : "the curve is still falling at its longest tau: the bias "
                                    "instability is an upper bound; a longer record would show "
                                    "the floor");
  return r;
}

}  // namespace accelcal

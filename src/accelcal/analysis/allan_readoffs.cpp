#include "accelcal/analysis/allan_readoffs.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

// sqrt(2 ln 2 / pi): the Allan deviation of flicker noise relative to its coefficient B
// (IEEE Std 952-1997, Table C.1).
constexpr double kFlickerFloor = 0.664;
// A point belongs to the white region when the curve's local slope is at most -kSlopeLimit,
// to the random-walk region when it is at least +kSlopeLimit: the term of that slope is then
// the larger part of the variance.
constexpr double kSlopeLimit = 0.3;
// The local slope is the least-squares slope over the points within this many decades.
constexpr double kSlopeHalfWidthDecades = 0.25;

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

// d log(adev) / d log(tau) at each point: the least-squares slope over its neighbours within
// kSlopeHalfWidthDecades (smooths the scatter of single points).
std::vector<double> LocalSlopes(const std::vector<double>& tau_s, const std::vector<double>& adev) {
  const size_t n = tau_s.size();
  std::vector<double> slopes(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int count = 0;
    for (size_t j = 0; j < n; ++j) {
      const double x = std::log10(tau_s[j] / tau_s[i]);
      if (std::abs(x) > kSlopeHalfWidthDecades) continue;
      const double y = std::log10(adev[j]);
      sx += x, sy += y, sxx += x * x, sxy += x * y, ++count;
    }
    const double denominator = count * sxx - sx * sx;
    if (count >= 2 && denominator > 0) {
      slopes[i] = (count * sxy - sx * sy) / denominator;
    } else {  // isolated point: the slope to its nearest neighbour
      const size_t j = i + 1 < n ? i + 1 : i - 1;
      slopes[i] = std::log(adev[j] / adev[i]) / std::log(tau_s[j] / tau_s[i]);
    }
  }
  return slopes;
}

// The edf-weighted geometric mean of `coefficient(i)` over the points where `in_region(i)`;
// NaN when there is none.
template <typename InRegion, typename Coefficient>
double RegionCoefficient(size_t n, const std::vector<double>& edf, InRegion in_region,
                         Coefficient coefficient) {
  double sum_w = 0.0, sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (!in_region(i)) continue;
    const double c = coefficient(i);
    if (!(c > 0.0)) continue;
    const double w = edf.empty() ? 1.0 : edf[i];
    sum_w += w;
    sum += w * std::log(c);
  }
  return sum_w > 0.0 ? std::exp(sum / sum_w) : kNaN;
}

}  // namespace

AllanReadOffs ReadOffAllan(const std::vector<double>& tau_s, const std::vector<double>& adev,
                           const std::vector<double>& edf) {
  CheckInput(tau_s, adev, edf);
  const size_t n = tau_s.size();
  const std::vector<double> slope = LocalSlopes(tau_s, adev);
  AllanReadOffs r;

  // White noise: sigma = N / sqrt(tau) on the points of slope <= -kSlopeLimit.
  auto white = [&](size_t i) { return slope[i] <= -kSlopeLimit; };
  r.noise_density = RegionCoefficient(n, edf, white, [&](size_t i) { return adev[i] * std::sqrt(tau_s[i]); });
  r.white_noise_observed = !std::isnan(r.noise_density);
  if (!r.white_noise_observed) r.noise_density = adev.front() * std::sqrt(tau_s.front());

  // Random walk: sigma^2 = K^2 tau / 3 on the points of slope >= +kSlopeLimit, with the white
  // term (known from the short taus) taken off so the region's lower edge is not biased high.
  const double n2 = r.white_noise_observed ? r.noise_density * r.noise_density : 0.0;
  auto walk = [&](size_t i) { return slope[i] >= kSlopeLimit; };
  r.random_walk = RegionCoefficient(n, edf, walk, [&](size_t i) {
    return std::sqrt(std::max(0.0, adev[i] * adev[i] - n2 / tau_s[i]) * 3.0 / tau_s[i]);
  });
  r.random_walk_observed = !std::isnan(r.random_walk);
  if (!r.random_walk_observed) r.random_walk = adev.back() / std::sqrt(tau_s.back() / 3.0);

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

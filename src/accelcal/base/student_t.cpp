#include "accelcal/base/student_t.h"

#include <cmath>
#include <limits>

namespace accelcal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The density of Student's t (dof finite) or of the standard normal (dof infinite).
double Density(double t, double dof) {
  if (std::isinf(dof)) return std::exp(-0.5 * t * t) / std::sqrt(2.0 * kPi);
  const double log_norm = std::lgamma(0.5 * (dof + 1.0)) - std::lgamma(0.5 * dof) - 0.5 * std::log(dof * kPi);
  return std::exp(log_norm - 0.5 * (dof + 1.0) * std::log1p(t * t / dof));
}

// P(|T| <= t), t >= 0: twice the integral of the density over 0..t (composite Simpson).
double CentralProbability(double t, double dof) {
  const int n = 2000;  // even
  const double h = t / n;
  double sum = Density(0.0, dof) + Density(t, dof);
  for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * Density(i * h, dof);
  return 2.0 * sum * h / 3.0;
}

}  // namespace

double StudentTCoverageFactor(double p, double dof) {
  if (!(p > 0.0 && p < 1.0) || !(dof > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  double lo = 0.0, hi = 1.0;
  // Heavy tails at small dof: widen until the bracket holds p (t_0.9545(0.5) is far out).
  while (CentralProbability(hi, dof) < p) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) return std::numeric_limits<double>::infinity();
  }
  while (hi - lo > 1e-9 * hi) {
    const double mid = 0.5 * (lo + hi);
    (CentralProbability(mid, dof) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace accelcal

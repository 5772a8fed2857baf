#include "accelcal/diagnosis/chi_square.h"

#include <cmath>
#include <limits>

namespace accelcal {
namespace {

constexpr double kEps = 1e-15;
constexpr int kMaxTerms = 1000;

// P(a, x) = gamma(a, x) / Gamma(a) by the series x^a e^-x sum x^n / (a (a+1) ... (a+n)).
double LowerSeries(double a, double x) {
  double term = 1.0 / a;
  double sum = term;
  for (int n = 1; n < kMaxTerms; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::fabs(term) < std::fabs(sum) * kEps) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) = Gamma(a, x) / Gamma(a) by its continued fraction, evaluated with modified Lentz.
double UpperFraction(double a, double x) {
  constexpr double kTiny = std::numeric_limits<double>::min() / kEps;
  double b = x + 1.0 - a;
  double c = 1.0 / kTiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < kMaxTerms; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < kEps) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double ChiSquareSurvival(double chi2, int dof) {
  if (dof <= 0 || !(chi2 >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (chi2 == 0.0) return 1.0;
  const double a = 0.5 * dof;
  const double x = 0.5 * chi2;
  return x < a + 1.0 ? 1.0 - LowerSeries(a, x) : UpperFraction(a, x);
}

}  // namespace accelcal

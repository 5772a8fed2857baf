#include "accelcal/base/chi_square.h"

#include <cmath>
#include <limits>

namespace accelcal {
namespace {

constexpr double kEps = 1e-15;
constexpr int kMaxTerms = 20000;  // enough for a ~ 1e5 (the terms needed grow like sqrt(a))
// Above this many degrees of freedom the quantile uses the Wilson-Hilferty cube-root normal
// approximation (Johnson, Kotz & Balakrishnan, Continuous Univariate Distributions vol. 1,
// ch. 18), whose relative error falls like 1/dof (< 1e-6 here); the series and continued
// fraction would need ~sqrt(dof) terms per evaluation.
constexpr double kWilsonHilfertyDof = 2.0e5;

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

// The chi-square density at x for dof degrees of freedom (x > 0).
double ChiSquareDensity(double x, double dof) {
  const double a = 0.5 * dof;
  return std::exp((a - 1.0) * std::log(x) - 0.5 * x - a * std::log(2.0) - std::lgamma(a));
}

// The standard normal p-quantile by Newton steps on 0.5 erfc(-z / sqrt 2).
double NormalQuantile(double p) {
  double z = 0.0;
  for (int i = 0; i < 100; ++i) {
    const double f = 0.5 * std::erfc(-z / std::sqrt(2.0)) - p;
    const double density = std::exp(-0.5 * z * z) / std::sqrt(2.0 * M_PI);
    const double step = f / density;
    z -= step;
    if (std::fabs(step) < 1e-15 * (1.0 + std::fabs(z))) break;
  }
  return z;
}

}  // namespace

double ChiSquareCdf(double chi2, double dof) {
  if (!(dof > 0.0) || !(chi2 >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (chi2 == 0.0) return 0.0;
  if (std::isinf(chi2)) return 1.0;
  const double a = 0.5 * dof;
  const double x = 0.5 * chi2;
  return x < a + 1.0 ? LowerSeries(a, x) : 1.0 - UpperFraction(a, x);
}

double ChiSquareQuantile(double p, double dof) {
  if (!(p > 0.0 && p < 1.0) || !(dof > 0.0) || std::isinf(dof)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (dof > kWilsonHilfertyDof) {
    const double v = 2.0 / (9.0 * dof);
    const double root = 1.0 - v + NormalQuantile(p) * std::sqrt(v);
    return dof * root * root * root;
  }
  // Bracket [lo, hi] with Cdf(lo) <= p <= Cdf(hi), starting from the mean dof.
  double lo = 0.0;
  double hi = dof;
  while (ChiSquareCdf(hi, dof) < p) {
    lo = hi;
    hi *= 2.0;
  }
  double x = 0.5 * (lo + hi);
  for (int i = 0; i < 200; ++i) {
    const double f = ChiSquareCdf(x, dof) - p;
    if (f == 0.0) return x;
    if (f < 0.0) {
      lo = x;
    } else {
      hi = x;
    }
    const double density = ChiSquareDensity(x, dof);
    double next = density > 0.0 ? x - f / density : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::fabs(next - x) <= 1e-14 * x || hi - lo <= 1e-14 * hi) return next;
    x = next;
  }
  return x;
}

double ChiSquareSurvival(double chi2, int dof) {
  if (dof <= 0 || !(chi2 >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (chi2 == 0.0) return 1.0;
  const double a = 0.5 * dof;
  const double x = 0.5 * chi2;
  return x < a + 1.0 ? 1.0 - LowerSeries(a, x) : UpperFraction(a, x);
}

}  // namespace accelcal

#include "accelcal/analysis/allan_confidence.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "accelcal/base/chi_square.h"

namespace accelcal {
namespace {

// A figure the data do not define.
constexpr double kNotDefined = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<double> Differenced(const std::vector<double>& w) {
  std::vector<double> out;
  for (size_t k = 1; k < w.size(); ++k) out.push_back(w[k] - w[k - 1]);
  return out;
}

// Barnes' B1(N, mu) (NIST SP 1065 eq. (67)); mu = 0 is its limit N ln N / (2 (N-1) ln 2).
double B1Theory(double n, int mu) {
  if (mu == 0) return n * std::log(n) / (2.0 * (n - 1.0) * std::log(2.0));
  return n * (1.0 - std::pow(n, mu)) / (2.0 * (n - 1.0) * (1.0 - std::pow(2.0, mu)));
}

// ---- Greenhall & Riley 2003, d = 2 (Allan variance), unmodified ----

// Eq. (7): the generalized autocovariance kernel of the phase for noise exponent alpha. Signs
// are immaterial (the EDF is a ratio of squares of linear combinations of one kernel).
double Sw(double t, int alpha) {
  const double a = std::fabs(t);
  switch (alpha) {
    case 2: return -a;
    case 1: return a == 0.0 ? 0.0 : t * t * std::log(a);
    case 0: return a * a * a;
    case -1: return a == 0.0 ? 0.0 : -t * t * t * t * std::log(a);
    case -2: return -a * a * a * a * a;
    default: return kNotDefined;
  }
}

// Eq. (8): filtering by the frequency average over 1/F; F = infinity is its limit.
double Sx(double t, double f, int alpha) {
  if (std::isinf(f)) return Sw(t, alpha + 2);
  return f * f * (2.0 * Sw(t, alpha) - Sw(t - 1.0 / f, alpha) - Sw(t + 1.0 / f, alpha));
}

// Eq. (9) for d = 2: the second difference's kernel.
double Sz(double t, double f, int alpha) {
  return 6.0 * Sx(t, f, alpha) - 4.0 * Sx(t - 1.0, f, alpha) - 4.0 * Sx(t + 1.0, f, alpha) +
         Sx(t - 2.0, f, alpha) + Sx(t + 2.0, f, alpha);
}

// Eq. (10): the basic sum.
double BasicSum(double j_terms, double m_terms, double s, double f, int alpha) {
  const double s0 = Sz(0.0, f, alpha);
  const double sj = Sz(j_terms / s, f, alpha);
  double sum = s0 * s0 + (1.0 - j_terms / m_terms) * sj * sj;
  for (int j = 1; j < static_cast<int>(j_terms); ++j) {
    const double v = Sz(j / s, f, alpha);
    sum += 2.0 * (1.0 - j / m_terms) * v * v;
  }
  return sum;
}

// Table 2, column d = 2: (a0, a1) for alpha = 2, 1, 0, -1, -2.
void Table2(int alpha, double* a0, double* a1) {
  static constexpr double kA0[] = {35.0 / 18.0, 790.0, 2.0 / 3.0, 0.852, 1.079};
  static constexpr double kA1[] = {1.0, 410.0, 1.0 / 3.0, 0.375, 0.368};
  *a0 = kA0[2 - alpha];
  *a1 = kA1[2 - alpha];
}
// Table 3, d = 2 (alpha = 1): b0 + b1 ln m.
constexpr double kB0 = 15.23;
constexpr double kB1 = 12.0;
constexpr double kJmax = 100.0;
constexpr double kD = 2.0;

}  // namespace

std::string NoiseIdMethodToString(NoiseIdMethod method) {
  switch (method) {
    case NoiseIdMethod::kNone: return "none";
    case NoiseIdMethod::kLag1Acf: return "lag1_acf";
    case NoiseIdMethod::kB1Ratio: return "b1_ratio";
  }
  return "none";
}

double Lag1Autocorrelation(std::span<const double> w) {
  const size_t n = w.size();
  if (n < 2) return kNotDefined;
  double mean = 0.0;
  for (double v : w) mean += v;
  mean /= static_cast<double>(n);
  double num = 0.0;
  double den = 0.0;
  for (size_t k = 0; k < n; ++k) {
    const double a = w[k] - mean;
    den += a * a;
    if (k + 1 < n) num += a * (w[k + 1] - mean);
  }
  const double nd = static_cast<double>(n);
  return den > 0.0 ? (num / nd) / (den / (nd - 1.0)) : kNotDefined;
}

std::array<double, 3> Lag1Autocorrelations(std::span<const double> z) {
  std::array<double, 3> r1 = {kNotDefined, kNotDefined, kNotDefined};
  std::vector<double> series(z.begin(), z.end());
  for (int d = 0; d < 3; ++d) {
    r1[d] = Lag1Autocorrelation(series);
    series = Differenced(series);
  }
  return r1;
}

int Lag1NoiseAlpha(const std::array<double, 3>& r1) {
  for (int d = 0; d < 3; ++d) {
    const double delta = r1[d] / (1.0 + r1[d]);
    if (!std::isfinite(delta)) return 0;  // a constant series: nothing to identify
    if (delta < 0.25 || d == 2) {
      const int alpha = -static_cast<int>(std::nearbyint(2.0 * delta)) - 2 * d;
      return std::clamp(alpha, -2, 2);
    }
  }
  return 0;
}

int B1NoiseAlpha(double b1, double n) {
  int mu = -2;
  for (int hi = -1; hi <= 1; ++hi) {
    const double boundary = std::sqrt(B1Theory(n, hi - 1) * B1Theory(n, hi));
    if (b1 > boundary) mu = hi;
  }
  return mu == -2 ? 2 : -1 - mu;  // mu 1, 0, -1 -> alpha -2, -1, 0
}

int ResolvePhaseNoise(double rn, int64_t m) {
  const double md = static_cast<double>(m);
  const double white = 1.0 / md;
  const double flicker = (3.0 * std::log(256.0 / 27.0) / (8.0 * M_PI * M_PI)) /
                         ((1.038 + 3.0 * std::log(M_PI * md)) / (4.0 * M_PI * M_PI));
  if (!(rn > 0.0)) return 2;
  return std::fabs(std::log(rn / flicker)) < std::fabs(std::log(rn / white)) ? 1 : 2;
}

double AllanEdf(int alpha, int64_t m, int64_t stride, int64_t phase_points) {
  if (m < 1 || stride < 1 || m % stride != 0 || alpha < -2 || alpha > 2) return kNotDefined;
  const int64_t span = phase_points - 1 - 2 * m;  // N - L with L = m/F + m d = 1 + 2m
  if (span < 0) return kNotDefined;
  const double s = static_cast<double>(m / stride);  // stride factor S
  const double big_m = 1.0 + static_cast<double>(span / stride);
  const double j = std::min(big_m, (kD + 1.0) * s);
  const double r = big_m / s;
  const double md = static_cast<double>(m);
  if (alpha <= 0) {
    if (j <= kJmax) {
      const double f = md * (kD + 1.0) <= kJmax ? md : kInf;
      const double s0 = Sz(0.0, f, alpha);
      return s0 * s0 * big_m / BasicSum(j, big_m, s, f, alpha);
    }
    if (r > kD + 1.0) {
      double a0, a1;
      Table2(alpha, &a0, &a1);
      return r / (a0 - a1 / r);
    }
    const double s0 = Sz(0.0, kInf, alpha);
    return s0 * s0 * kJmax / BasicSum(kJmax, kJmax, kJmax / r, kInf, alpha);
  }
  if (alpha == 1) {
    if (j <= kJmax) {
      const double s0 = Sz(0.0, md, 1);
      return s0 * s0 * big_m / BasicSum(j, big_m, s, md, 1);
    }
    const double b = kB0 + kB1 * std::log(md);
    if (r > kD + 1.0) {
      double a0, a1;
      Table2(1, &a0, &a1);
      return b * b * r / (a0 - a1 / r);
    }
    const double mp = kJmax / r;
    return b * b * kJmax / BasicSum(kJmax, kJmax, mp, mp, 1);
  }
  // alpha = 2: the terms are correlated only when they share phase points.
  if (std::ceil(r) <= kD && j <= 10.0 * kJmax) {
    const double s0 = Sz(0.0, md, 2);
    return s0 * s0 * big_m / BasicSum(j, big_m, s, md, 2);
  }
  double a0, a1;
  Table2(2, &a0, &a1);
  return big_m / (a0 - a1 / r);
}

namespace {

// Stable32's chi-square quantile above 100 degrees of freedom (see ChiSquareMethod::kStable32):
// A&S 26.2.22 for the normal quantile, t = sqrt(ln(1 / q^2)) for the smaller tail q, then
// A&S 26.4.17.
double Stable32ChiSquareQuantile(double p, double edf) {
  if (edf <= 100.0) return ChiSquareQuantile(p, edf);
  const double q = p < 0.5 ? p : 1.0 - p;
  const double t = std::sqrt(std::log(1.0 / (q * q)));
  const double upper = t - (2.30753 + 0.27601 * t) / (1.0 + 0.99229 * t + 0.04481 * t * t);
  const double x = p < 0.5 ? -upper : upper;
  const double v = 2.0 / (9.0 * edf);
  const double root = 1.0 - v + x * std::sqrt(v);
  return edf * root * root * root;
}

}  // namespace

DeviationBounds ChiSquareDeviationBounds(double dev, double edf, double confidence,
                                         ChiSquareMethod method) {
  const double tail = 0.5 * (1.0 - confidence);
  auto quantile = [&](double p) {
    return method == ChiSquareMethod::kStable32 ? Stable32ChiSquareQuantile(p, edf)
                                                : ChiSquareQuantile(p, edf);
  };
  DeviationBounds b;
  b.lo = dev * std::sqrt(edf / quantile(1.0 - tail));
  b.hi = dev * std::sqrt(edf / quantile(tail));
  return b;
}

}  // namespace accelcal

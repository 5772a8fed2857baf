#include "accelcal/analysis/normality.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/capture.h"
#include "accelcal/base/error.h"

namespace accelcal::analysis {

std::string_view NormalityVerdictToString(NormalityVerdict v) {
  switch (v) {
    case NormalityVerdict::kNormal: return "normal";
    case NormalityVerdict::kNotNormal: return "not normal";
    case NormalityVerdict::kQuantized: return "quantized";
  }
  return "normal";
}

std::optional<NormalityVerdict> StringToNormalityVerdict(std::string_view text) {
  for (NormalityVerdict v :
       {NormalityVerdict::kNormal, NormalityVerdict::kNotNormal, NormalityVerdict::kQuantized}) {
    if (NormalityVerdictToString(v) == text) return v;
  }
  return std::nullopt;
}

NormalityTest JarqueBera(const std::vector<double>& x, double std_counts, double alpha,
                         double quantization_limit_counts) {
  const long n = static_cast<long>(x.size());
  if (n < 8) throw Error(fmt::format("normality test: {} values are too few (at least 8)", n));
  // Skewness and kurtosis do not depend on the unit: the values are divided by the largest
  // magnitude first, so readings near 1e308 give moments, not inf and then nan.
  double largest = 0.0;
  for (double v : x) {
    if (!std::isfinite(v)) throw Error("normality test: a value is not a finite number");
    largest = std::max(largest, std::fabs(v));
  }
  const double unit = largest > 0.0 ? largest : 1.0;
  double mean = 0.0;
  for (double v : x) mean += v / unit;
  mean /= static_cast<double>(n);
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;  // central moments (1/n), in units of `unit`
  for (double v : x) {
    const double d = v / unit - mean;
    const double d2 = d * d;
    m2 += d2;
    m3 += d2 * d;
    m4 += d2 * d2;
  }
  m2 /= static_cast<double>(n);
  m3 /= static_cast<double>(n);
  m4 /= static_cast<double>(n);
  return JarqueBeraOfMoments(n, m2, m3, m4, std_counts, alpha, quantization_limit_counts);
}

NormalityTest JarqueBeraOfMoments(long n, double m2, double m3, double m4, double std_counts,
                                  double alpha, double quantization_limit_counts) {
  if (n < 8) throw Error(fmt::format("normality test: {} values are too few (at least 8)", n));
  NormalityTest t;
  t.n = n;
  if (!(m2 > 0.0)) {
    if (!(std_counts < quantization_limit_counts))
      throw Error("normality test: all values are equal");
    t.skewness = t.excess_kurtosis = t.statistic = t.p_value = kNaN;
    t.verdict = NormalityVerdict::kQuantized;
    t.note = "every reading is the same count: the ADC's rounding hides the noise";
    return t;
  }
  t.skewness = m3 / std::pow(m2, 1.5);
  t.excess_kurtosis = m4 / (m2 * m2) - 3.0;
  t.statistic = static_cast<double>(n) / 6.0 *
                (t.skewness * t.skewness + 0.25 * t.excess_kurtosis * t.excess_kurtosis);
  t.p_value = std::exp(-0.5 * t.statistic);
  if (std_counts < quantization_limit_counts) {
    t.verdict = NormalityVerdict::kQuantized;
    t.note = fmt::format(
        "std {:.2f} counts is below {:g} count: the ADC's rounding dominates the distribution, "
        "so a normality test says nothing (Jarque-Bera p = {:.2g} not used)",
        std_counts, quantization_limit_counts, t.p_value);
  } else if (t.p_value < alpha) {
    t.verdict = NormalityVerdict::kNotNormal;
    t.note = fmt::format("Jarque-Bera p = {:.2g} < {:g} (skewness {:.3f}, excess kurtosis {:.3f})",
                         t.p_value, alpha, t.skewness, t.excess_kurtosis);
  } else {
    t.verdict = NormalityVerdict::kNormal;
    t.note = fmt::format("Jarque-Bera p = {:.2g} >= {:g}", t.p_value, alpha);
  }
  return t;
}

}  // namespace accelcal::analysis

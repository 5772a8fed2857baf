// Normality check of a sample: the Jarque-Bera test (C. M. Jarque, A. K. Bera, "A test for
// normality of observations and regression residuals", International Statistical Review
// 55(2), 1987): JB = n/6 (S^2 + (K - 3)^2 / 4) with S the skewness and K the kurtosis (moment
// estimates), asymptotically chi-square with 2 degrees of freedom, so p = exp(-JB / 2).
//
// ADC quantization: a reading rounded to whole counts is a discrete variable. When its std is
// well above one count the rounding changes skewness and kurtosis negligibly (Sheppard's
// corrections), but below about one count the record takes only a handful of values and a
// large n makes any test reject normality because of the rounding alone. The check then says
// so (kQuantized) instead of a false "not normal".
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace accelcal::analysis {

enum class NormalityVerdict { kNormal, kNotNormal, kQuantized };
std::string_view NormalityVerdictToString(NormalityVerdict v);  // "normal", "not normal", "quantized"
std::optional<NormalityVerdict> StringToNormalityVerdict(std::string_view text);

struct NormalityTest {
  long n = 0;
  double skewness = 0.0;
  double excess_kurtosis = 0.0;  // K - 3
  double statistic = 0.0;        // JB
  double p_value = 1.0;          // chi-square(2) tail of JB
  NormalityVerdict verdict = NormalityVerdict::kNormal;
  std::string note;  // why, in words
};

// Tests `x`. `std_counts` is the record's std in ADC counts (for the quantization rule: below
// `quantization_limit_counts` the verdict is kQuantized); `alpha` the significance level below
// which the p-value means "not normal". Throws accelcal::Error for fewer than 8 values, or
// values all equal while std_counts is above the quantization limit (nothing to test).
NormalityTest JarqueBera(const std::vector<double>& x, double std_counts, double alpha = 0.01,
                         double quantization_limit_counts = 1.0);

// The same test from the central moments (1/n) of n values (n >= 8), in any one unit (the
// vector form divides the values by their largest magnitude first): for a record read as it
// comes (noise_analysis.h). Throws as JarqueBera for a zero m2 above the quantization limit.
NormalityTest JarqueBeraOfMoments(long n, double m2, double m3, double m4, double std_counts,
                                  double alpha = 0.01, double quantization_limit_counts = 1.0);

}  // namespace accelcal::analysis

#include "accelcal/report/uncertainty_text.h"

#include <cmath>

#include <fmt/core.h>

namespace accelcal {

RoundedResult RoundToUncertainty(double value, double expanded) {
  RoundedResult r;
  if (!std::isfinite(value)) {
    r.value = "-";
    r.uncertainty = std::isfinite(expanded) && expanded > 0.0 ? fmt::format("{:.2g}", expanded) : "-";
    return r;
  }
  if (!(std::isfinite(expanded) && expanded > 0.0)) {
    r.value = fmt::format("{:.6g}", value);
    r.uncertainty = "-";
    return r;
  }
  // The decimal place of U's second significant digit (from U once rounded, so 0.0996 -> 0.10).
  int exponent = static_cast<int>(std::floor(std::log10(expanded)));
  const double unit = std::pow(10.0, exponent - 1);
  if (std::round(expanded / unit) >= 100.0) ++exponent;
  const int place = exponent - 1;  // 10^place is the last digit shown
  const double step = std::pow(10.0, place);
  const double u = std::round(expanded / step) * step;
  double v = std::round(value / step) * step;
  if (v == 0.0) v = 0.0;  // no "-0"
  const int decimals = place < 0 ? -place : 0;
  r.value = fmt::format("{:.{}f}", v, decimals);
  r.uncertainty = fmt::format("{:.{}f}", u, decimals);
  return r;
}

}  // namespace accelcal

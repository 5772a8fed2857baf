#include "tui/gauge.h"

#include <algorithm>
#include <cmath>

namespace accelcal::ui {

std::string Bar(double fraction, int inner) {
  inner = std::max(inner, 1);
  if (std::isnan(fraction)) return "[" + std::string(inner, '-') + "]";
  if (fraction >= 1.0) return "[" + std::string(inner - 1, '#') + "!]";
  const int filled = std::clamp(static_cast<int>(std::lround(fraction * inner)), 0, inner);
  return "[" + std::string(filled, '#') + std::string(inner - filled, '.') + "]";
}

}  // namespace accelcal::ui

#include "accelcal/report/device_history.h"

#include <cmath>
#include <limits>

namespace accelcal {

ParameterMove MoveBetween(double previous, double previous_sigma, double value, double sigma) {
  ParameterMove m;
  m.delta = value - previous;
  m.sigma_combined = std::hypot(previous_sigma, sigma);
  m.n_sigmas = m.sigma_combined > 0.0 ? std::fabs(m.delta) / m.sigma_combined
               : m.delta == 0.0       ? 0.0
                                      : std::numeric_limits<double>::infinity();
  m.changed = m.n_sigmas > kChangedSigmas;
  return m;
}

}  // namespace accelcal

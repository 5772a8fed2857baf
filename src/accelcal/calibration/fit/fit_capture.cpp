#include "accelcal/calibration/fit/fit_capture.h"

namespace accelcal {

FitCapture MakeFitCapture(const Capture& capture) {
  const CaptureStats& stats = capture.stats();
  FitCapture c;
  c.id = capture.id;
  c.kind = capture.kind;
  c.radius_m = capture.radius_m;
  c.rpm = capture.rpm;
  c.up_axis = capture.up_axis;
  c.n_samples = stats.n;
  c.mean_counts = stats.mean_counts;
  c.mean_t_s = stats.mean_t_s;
  c.mean_temp_c = stats.mean_temp_c;
  Eigen::Matrix3d cov = stats.n >= 2 ? stats.Covariance()
                                     : Eigen::Matrix3d::Zero();
  constexpr double kQuantizationVarianceCounts2 = 1.0 / 12.0;
  for (int i = 0; i < 3; ++i) cov(i, i) = std::max(cov(i, i), kQuantizationVarianceCounts2);
  c.mean_cov_counts2 = cov / double(std::max<long>(stats.n, 1));
  return c;
}

}  // namespace accelcal

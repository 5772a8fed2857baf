// What the fit uses of one capture: its mean reading, the uncertainty of that mean, and the
// conditions it was taken in (which decide the reference magnitude and feed the effects).
#pragma once

#include <Eigen/Core>

#include "accelcal/base/capture.h"

namespace accelcal {

struct FitCapture {
  int id = 0;
  CaptureKind kind = CaptureKind::kStatic;
  Eigen::Vector3d mean_counts = Eigen::Vector3d::Zero();
  // Covariance of the mean reading, counts^2. The per-sample covariance (of a turntable run: less
  // its once-per-revolution swing at the stated speed, which averages out of the mean) is
  // floored at the quantization variance (1/12 count^2 per axis) so a perfectly steady
  // quantized signal does not get an infinite weight; then divided by the sample count
  // (white-noise assumption).
  Eigen::Matrix3d mean_cov_counts2 = Eigen::Matrix3d::Identity();
  long n_samples = 0;
  double radius_m = kNaN;  // turntable only, as stated by the operator
  double rpm = kNaN;       // turntable only, as stated by the operator
  // Turntable only: radius_m's standard uncertainty that is this run's own (Capture's), m. The
  // fit weighs the run by it too (ResidualSigmas), the budget lists what it leaves uncertain.
  double radius_own_u_m = 0.0;
  std::optional<SensorAxis> up_axis;  // turntable only, when known: the axis that pointed up
  double mean_t_s = kNaN;
  double mean_temp_c = kNaN;
};

// Statistics of `capture` for the fit (the capture must have at least 2 finite samples). A
// capture that was still settling (Capture::settled) gives its settled reading and its covariance.
FitCapture MakeFitCapture(const Capture& capture);

}  // namespace accelcal

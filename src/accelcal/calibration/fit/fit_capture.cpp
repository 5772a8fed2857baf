#include "accelcal/calibration/fit/fit_capture.h"

#include <cmath>

#include <Eigen/Cholesky>

namespace accelcal {
namespace {

// The per-sample covariance of a turntable run without its once-per-revolution swing: a spin
// axis tilted by theta turns gravity's in-plane part g sin(theta) once per revolution in the
// sensor frame. That swing averages out of the mean over whole revolutions, so it is no noise of
// the mean; counted as noise it would inflate the run's sigma several times and hide the tilt
// (issue 13). Each axis less a least-squares c0 + a cos(w t) + b sin(w t) at the stated speed;
// the residuals' covariance over n - 3. Empty optional when it cannot be computed.
std::optional<Eigen::Matrix3d> SwingFreeCovariance(const Capture& capture) {
  const double w = RpmToRadPerS(capture.rpm);
  if (capture.kind != CaptureKind::kTurntable || !(w > 0.0) || capture.samples.size() < 10)
    return std::nullopt;
  const double t0 = capture.samples.front().t_s;
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d rhs = Eigen::Matrix3d::Zero();  // one column per axis
  long n = 0;
  for (const Sample& s : capture.samples) {
    if (!std::isfinite(s.t_s) || !s.raw_counts.allFinite()) continue;
    const Eigen::Vector3d row(1.0, std::cos(w * (s.t_s - t0)), std::sin(w * (s.t_s - t0)));
    normal += row * row.transpose();
    rhs += row * s.raw_counts.transpose();
    ++n;
  }
  if (n < 10) return std::nullopt;
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(normal);
  if (ldlt.info() != Eigen::Success) return std::nullopt;
  const Eigen::Matrix3d coef = ldlt.solve(rhs);
  Eigen::Matrix3d comoment = Eigen::Matrix3d::Zero();
  for (const Sample& s : capture.samples) {
    if (!std::isfinite(s.t_s) || !s.raw_counts.allFinite()) continue;
    const Eigen::Vector3d row(1.0, std::cos(w * (s.t_s - t0)), std::sin(w * (s.t_s - t0)));
    const Eigen::Vector3d r = s.raw_counts - coef.transpose() * row;
    comoment += r * r.transpose();
  }
  return comoment / static_cast<double>(n - 3);
}

}  // namespace

FitCapture MakeFitCapture(const Capture& capture) {
  const CaptureStats& stats = capture.stats();
  FitCapture c;
  c.id = capture.id;
  c.kind = capture.kind;
  c.radius_m = capture.radius_m;
  c.rpm = capture.rpm;
  c.radius_own_u_m = capture.radius_own_u_m;
  c.up_axis = capture.up_axis;
  c.n_samples = stats.n;
  c.mean_counts = stats.mean_counts;
  c.mean_t_s = stats.mean_t_s;
  c.mean_temp_c = stats.mean_temp_c;
  Eigen::Matrix3d cov = stats.n >= 2 ? stats.Covariance()
                                     : Eigen::Matrix3d::Zero();
  if (const std::optional<Eigen::Matrix3d> swing_free = SwingFreeCovariance(capture)) cov = *swing_free;
  constexpr double kQuantizationVarianceCounts2 = 1.0 / 12.0;
  for (int i = 0; i < 3; ++i) cov(i, i) = std::max(cov(i, i), kQuantizationVarianceCounts2);
  c.mean_cov_counts2 = cov / double(std::max<long>(stats.n, 1));
  if (capture.settled) {
    c.mean_counts = capture.settled->mean_counts;
    c.mean_cov_counts2 = capture.settled->mean_cov_counts2;
  }
  return c;
}

}  // namespace accelcal

#include "accelcal/calibration/pose_check.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/core.h>

namespace accelcal {

double PoseAngleDeg(const Capture& capture, const SensorModel& model) {
  if (capture.kind != CaptureKind::kStatic || !capture.requested_up || capture.samples.empty())
    return kNaN;
  const Eigen::Vector3d measured = model.Calibrate(capture.stats().mean_counts);
  const Eigen::Vector3d& requested = *capture.requested_up;
  if (!(measured.norm() > 0.0) || !(requested.norm() > 0.0)) return kNaN;
  const double c = std::clamp(measured.normalized().dot(requested.normalized()), -1.0, 1.0);
  return std::acos(c) * 180.0 / std::numbers::pi;
}

std::vector<std::string> CheckRequestedPoses(const std::vector<Capture>& captures,
                                             const SensorModel& model, double tolerance_deg) {
  std::vector<std::string> out;
  for (const Capture& c : captures) {
    if (!c.used()) continue;
    const double angle = PoseAngleDeg(c, model);
    if (!(angle > tolerance_deg)) continue;
    const Eigen::Vector3d r = c.requested_up->normalized();
    const Eigen::Vector3d m = model.Calibrate(c.stats().mean_counts).normalized();
    out.push_back(fmt::format(
        "capture {}{}: the measured up ({:.2f}, {:.2f}, {:.2f}) is {:.1f} deg from the requested "
        "up ({:.2f}, {:.2f}, {:.2f}), beyond the {:g} deg tolerance; was it taken in another pose?",
        c.id, c.label.empty() ? "" : fmt::format(" ('{}')", c.label), m.x(), m.y(), m.z(), angle,
        r.x(), r.y(), r.z(), tolerance_deg));
  }
  return out;
}

}  // namespace accelcal

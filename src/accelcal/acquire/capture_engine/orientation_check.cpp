#include "accelcal/acquire/capture_engine/orientation_check.h"

#include <cmath>

#include <Eigen/Geometry>
#include <fmt/format.h>

namespace accelcal {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

bool IsFace(const Eigen::Vector3d& up) {
  for (const NamedPose& face : PrismFaces()) {
    if ((up.normalized() - face.up).norm() < 1e-6) return true;
  }
  return false;
}

std::string NameOf(const NamedPose& pose) {
  return pose.name.empty() ? DescribeUp(pose.up) : pose.name;
}

// The face or known pose (other than the expected one) nearest to `up`, and its angle.
std::pair<const NamedPose*, double> Nearest(const Eigen::Vector3d& up,
                                            const std::vector<NamedPose>& candidates,
                                            const NamedPose& expected) {
  const NamedPose* best = nullptr;
  double best_deg = kNaN;
  for (const NamedPose& pose : candidates) {
    if (AngleBetweenDeg(pose.up, expected.up) < 1e-6) continue;
    const double deg = AngleBetweenDeg(up, pose.up);
    if (best == nullptr || deg < best_deg) {
      best = &pose;
      best_deg = deg;
    }
  }
  return {best, best_deg};
}

std::string WrongPoseReason(const NamedPose& found, const NamedPose& expected) {
  if (IsFace(found.up)) {
    return fmt::format("the prism sits on the wrong face: {} is up, expected {}",
                       DescribeUp(found.up), NameOf(expected));
  }
  return fmt::format("the sensor is in pose '{}', expected '{}'", NameOf(found), NameOf(expected));
}

}  // namespace

std::string OrientationOptions::Validate() const {
  if (!(tolerance_deg > 0.0 && tolerance_deg < 45.0))
    return fmt::format("tolerance_deg is {}, must be in (0, 45) deg", tolerance_deg);
  if (!(duplicate_tolerance_deg > 0.0 && duplicate_tolerance_deg < 90.0))
    return fmt::format("duplicate_tolerance_deg is {}, must be in (0, 90) deg",
                       duplicate_tolerance_deg);
  return {};
}

std::vector<NamedPose> PrismFaces() {
  return {{"+x", Eigen::Vector3d::UnitX()},  {"-x", -Eigen::Vector3d::UnitX()},
          {"+y", Eigen::Vector3d::UnitY()},  {"-y", -Eigen::Vector3d::UnitY()},
          {"+z", Eigen::Vector3d::UnitZ()},  {"-z", -Eigen::Vector3d::UnitZ()}};
}

double AngleBetweenDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  // atan2 of |a x b| and a.b stays accurate for small and near-180 deg angles (acos does not).
  return std::atan2(a.cross(b).norm(), a.dot(b)) * kRadToDeg;
}

OrientationVerdict CheckOrientation(const Eigen::Vector3d& mean_raw_counts,
                                    const SensorModel& rough_model, const NamedPose& expected,
                                    const std::vector<CapturedPose>& captured,
                                    const std::vector<NamedPose>& known_poses,
                                    const OrientationOptions& options) {
  OrientationVerdict v;
  v.up_measured = rough_model.Calibrate(mean_raw_counts).normalized();
  v.angle_to_expected_deg = AngleBetweenDeg(v.up_measured, expected.up);
  std::vector<NamedPose> candidates = PrismFaces();
  candidates.insert(candidates.end(), known_poses.begin(), known_poses.end());
  const auto [nearest, nearest_deg] = Nearest(v.up_measured, candidates, expected);
  const bool expected_nearest = nearest == nullptr || v.angle_to_expected_deg <= nearest_deg;
  v.nearest_pose = expected_nearest ? NameOf(expected) : NameOf(*nearest);

  for (const CapturedPose& pose : captured) {
    if (AngleBetweenDeg(v.up_measured, pose.up) <= options.duplicate_tolerance_deg) {
      v.reason = fmt::format("this pose was already captured as capture {} ({})",
                             pose.capture_id, pose.label);
      return v;
    }
  }
  if (v.angle_to_expected_deg <= options.tolerance_deg) {
    v.ok = true;
    return v;
  }
  if (!expected_nearest && nearest_deg <= options.tolerance_deg) {
    v.reason = WrongPoseReason(*nearest, expected);
    return v;
  }
  v.reason = fmt::format("gravity is {:.1f} deg from the expected pose ({}), tolerance {:.3g} deg",
                         v.angle_to_expected_deg, NameOf(expected), options.tolerance_deg);
  return v;
}

}  // namespace accelcal

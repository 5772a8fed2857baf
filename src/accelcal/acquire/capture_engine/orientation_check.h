// Is the sensor in the pose the procedure asks for? Judged from the direction of the measured
// specific force (gravity's reaction: "up") through a rough model, before any fit: a datasheet
// scale and bias, or an earlier calibration. The rough model only needs to be good to a few
// degrees: a 5 % scale error or a bias of 5 % of g turns the direction by at most ~3 deg.
//
//   up_measured = normalize(T K^-1 (mean_raw - b))     (sensor_model.h; platform frame)
//
// In order:
//   1. Already captured: up_measured within duplicate_tolerance_deg of a pose captured
//      before -> refused: "this pose was already captured as capture 3 (z up)".
//   2. Expected: within tolerance_deg of the expected up -> accepted.
//   3. Wrong face: within tolerance_deg of one of the six faces (+-x, +-y, +-z up) or another
//      known pose of the procedure -> "the prism sits on the wrong face: -y is up, expected +z"
//      (or "the sensor is in pose 'tilted +x+y-z', expected 'z up'" for a known pose).
//   4. Otherwise: "gravity is 35.2 deg from the expected pose (+z up), tolerance 10 deg".
// Units: deg for the tolerances and angles (they are shown to the operator), m/s^2 inside.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

struct OrientationOptions {
  // Largest angle between the measured and the expected up that is accepted, deg; (0, 45).
  double tolerance_deg = 15.0;
  // A pose within this angle of a captured one is the same pose, deg; (0, 90).
  double duplicate_tolerance_deg = 15.0;

  std::string Validate() const;
};

// A named direction of "up" in the platform frame (need not be unit; it is normalized).
struct NamedPose {
  std::string name;  // "+z", "z up", "tilted +x+y+z"
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
};

// A pose captured earlier in the session.
struct CapturedPose {
  int capture_id = 0;
  std::string label;
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // measured (or planned) up, platform frame
};

struct OrientationVerdict {
  bool ok = false;
  std::string reason;  // empty when ok; else in words (see the header comment)
  Eigen::Vector3d up_measured = Eigen::Vector3d::Constant(kNaN);  // unit, platform frame
  double angle_to_expected_deg = kNaN;
  std::string nearest_pose;  // the name of the face or known pose nearest to up_measured
};

// The six faces of a prism as named poses: "+x" (x up), "-x", ..., "-z".
std::vector<NamedPose> PrismFaces();

// The check of the header comment. `expected` names the pose asked for; `known_poses` are the
// procedure's other poses (may be empty; the six faces are always known).
OrientationVerdict CheckOrientation(const Eigen::Vector3d& mean_raw_counts,
                                    const SensorModel& rough_model, const NamedPose& expected,
                                    const std::vector<CapturedPose>& captured,
                                    const std::vector<NamedPose>& known_poses,
                                    const OrientationOptions& options);

// Angle between two directions (any length, not zero), deg.
double AngleBetweenDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace accelcal

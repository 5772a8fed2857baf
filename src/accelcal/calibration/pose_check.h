// Was each capture taken in the pose it was asked for? A capture set may state, per static
// capture, the up direction the procedure requested (its `up` column, io/capture_set_reader.h);
// the fit cannot see a capture taken on the wrong face by itself (the magnitude of gravity is the
// same on every face), so after the fit each such capture's measured up direction is compared
// with the requested one:
//
//   up_measured = normalize(T K^-1 (mean_raw - b))   with the fitted model (sensor_model.h)
//
// and a warning names every capture whose angle to the requested up exceeds tolerance_deg (the
// procedure's orientation tolerance, 15 deg by default: session/procedure.h). Captures without a
// requested up, left out of the fit, or turntable captures are not judged.
#pragma once

#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

inline constexpr double kDefaultPoseToleranceDeg = 15.0;

// The angle between the measured and the requested up of a static capture, deg; NaN when the
// capture states no requested up, has no samples or is not static.
double PoseAngleDeg(const Capture& capture, const SensorModel& model);

// One warning per capture beyond tolerance_deg, in words: "capture 4 ('z down'): measured up is
// 178.9 deg from the requested up (-0.00, 0.00, -1.00); was it taken on another face?".
std::vector<std::string> CheckRequestedPoses(const std::vector<Capture>& captures,
                                             const SensorModel& model,
                                             double tolerance_deg = kDefaultPoseToleranceDeg);

}  // namespace accelcal

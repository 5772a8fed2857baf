// Leveling the table by the reversal method. The bias is unknown before the fit, so one reading
// cannot tell a tilted table from an offset sensor. Measure with the prism +z up, turn it 180 deg
// about the vertical, measure again: the table's tilt turns with the sensor's x and y, the
// sensor's offsets do not, so half the difference is the true tilt:
//   h1 = t + e,  h2 = -t + e   =>   t = (h1 - h2) / 2
// where h = (f_x, f_y) / |f| is the horizontal part of the specific force (rough model) in the
// first position's sensor frame.
// Units: deg for the tilts (shown to the operator).
#pragma once

#include <string>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

// Tilt about x and y, deg, from one mean reading through the rough model (bias included:
// approximate). x: the y axis dips (positive: +y is low); y: the x axis dips (positive: +x low).
Eigen::Vector2d ApparentTiltDeg(const Eigen::Vector3d& mean_raw_counts, const SensorModel& rough);

// The true tilt from the two positions of the reversal, deg (same convention).
Eigen::Vector2d ReversalTiltDeg(const Eigen::Vector3d& first_raw_counts,
                                const Eigen::Vector3d& turned_raw_counts, const SensorModel& rough);

// The sensor's own offset the reversal measured: the part of the horizontal reading that stays
// with the sensor when it turns, e = (h1 + h2) / 2 (dimensionless, the first position's frame).
Eigen::Vector2d ReversalOffset(const Eigen::Vector3d& first_raw_counts,
                               const Eigen::Vector3d& turned_raw_counts, const SensorModel& rough);

// The live tilt with that offset taken out, deg (ApparentTiltDeg's convention): what the feet
// change. (With the prism turned 180 deg it is the tilt in the turned frame.)
Eigen::Vector2d TiltWithoutOffsetDeg(const Eigen::Vector3d& live_raw_counts, const SensorModel& rough,
                                     const Eigen::Vector2d& offset);
// The offset as the tilt it would fake, deg (for the screen: "sensor offset x 1.50 deg").
Eigen::Vector2d OffsetAsTiltDeg(const Eigen::Vector2d& offset);

// What to do, in words: empty when both tilts are within tolerance_deg; else e.g.
// "raise the right side by about 1.9 deg (x dips); lower the front by 0.4 deg (y rises)".
std::string LevelingAdvice(const Eigen::Vector2d& tilt_deg, double tolerance_deg);

}  // namespace accelcal

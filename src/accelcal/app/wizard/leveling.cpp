#include "accelcal/app/wizard/leveling.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

double Deg(double rad) { return rad * 180.0 / M_PI; }

// The horizontal part of the specific force over its magnitude: (x, y) of the unit "up".
Eigen::Vector2d Horizontal(const Eigen::Vector3d& raw_counts, const SensorModel& rough) {
  const Eigen::Vector3d f = rough.Calibrate(raw_counts);
  const double norm = f.norm();
  if (!(norm > 0.0)) return Eigen::Vector2d::Constant(kNaN);
  return Eigen::Vector2d(f.x() / norm, f.y() / norm);
}

Eigen::Vector2d ToTiltDeg(const Eigen::Vector2d& h) {
  // Up leaning towards +x means +x is high; report the dip of +x as the tilt about y.
  return Eigen::Vector2d(Deg(std::asin(std::clamp(-h.y(), -1.0, 1.0))),
                         Deg(std::asin(std::clamp(-h.x(), -1.0, 1.0))));
}

}  // namespace

Eigen::Vector2d ApparentTiltDeg(const Eigen::Vector3d& mean_raw_counts, const SensorModel& rough) {
  return ToTiltDeg(Horizontal(mean_raw_counts, rough));
}

Eigen::Vector2d ReversalTiltDeg(const Eigen::Vector3d& first_raw_counts,
                                const Eigen::Vector3d& turned_raw_counts, const SensorModel& rough) {
  // The turned reading is in the turned frame (x and y reversed): back to the first frame, its
  // tilt part changes sign again, so the difference of the raw horizontal parts is 2 t.
  const Eigen::Vector2d h1 = Horizontal(first_raw_counts, rough);
  const Eigen::Vector2d h2 = Horizontal(turned_raw_counts, rough);
  return ToTiltDeg((h1 - h2) / 2.0);
}

Eigen::Vector2d ReversalOffset(const Eigen::Vector3d& first_raw_counts,
                               const Eigen::Vector3d& turned_raw_counts, const SensorModel& rough) {
  return (Horizontal(first_raw_counts, rough) + Horizontal(turned_raw_counts, rough)) / 2.0;
}

Eigen::Vector2d TiltWithoutOffsetDeg(const Eigen::Vector3d& live_raw_counts, const SensorModel& rough,
                                     const Eigen::Vector2d& offset) {
  return ToTiltDeg(Horizontal(live_raw_counts, rough) - offset);
}

Eigen::Vector2d OffsetAsTiltDeg(const Eigen::Vector2d& offset) { return ToTiltDeg(offset); }

std::string LevelingAdvice(const Eigen::Vector2d& tilt_deg, double tolerance_deg) {
  std::string advice;
  auto add = [&](double dip_deg, const char* low_side, const char* high_side, const char* axis) {
    if (!(std::abs(dip_deg) > tolerance_deg)) return;
    if (!advice.empty()) advice += "; ";
    advice += fmt::format("raise the {} by about {:.1f} deg (+{} {})", dip_deg > 0 ? low_side
                          : high_side, std::abs(dip_deg), axis, dip_deg > 0 ? "dips" : "rises");
  };
  // With +x pointing right and +y to the back of the table.
  add(tilt_deg.y(), "right side", "left side", "x");
  add(tilt_deg.x(), "back", "front", "y");
  return advice;
}

}  // namespace accelcal

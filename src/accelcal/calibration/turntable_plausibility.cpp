#include "accelcal/calibration/turntable_plausibility.h"

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace accelcal {

bool IsPlausibleTurntableRadius(double radius_m) {
  return std::isfinite(radius_m) && radius_m >= kMinRadiusM && radius_m <= kMaxRadiusM;
}

bool IsPlausibleTurntableRpm(double rpm) {
  return std::isfinite(rpm) && rpm >= kMinRpm && rpm <= kMaxRpm;
}

std::string TurntableConditionsProblem(double radius_m, double rpm) {
  std::vector<std::string> problems;
  if (!IsPlausibleTurntableRadius(radius_m))
    problems.push_back(fmt::format("radius {:g} m is not a plausible turntable radius (expected "
                                   "{:g} mm to {:g} m)", radius_m, kMinRadiusM * 1000, kMaxRadiusM));
  if (!IsPlausibleTurntableRpm(rpm))
    problems.push_back(fmt::format("speed {:g} rpm is not a plausible turntable speed (expected "
                                   "{:g} to {:g} rpm)", rpm, kMinRpm, kMaxRpm));
  if (problems.empty()) return {};
  std::string text = fmt::format("stated {}", fmt::join(problems, " and "));
  // Each one plausible as the other: the two columns were likely swapped.
  if (problems.size() == 2 && IsPlausibleTurntableRadius(rpm) && IsPlausibleTurntableRpm(radius_m))
    text += ": are the radius and the speed swapped?";
  else if (!IsPlausibleTurntableRadius(radius_m) && IsPlausibleTurntableRadius(radius_m / 1000.0))
    text += fmt::format(": was the radius given in mm ({:g} mm = {:g} m)?", radius_m, radius_m / 1000.0);
  return text;
}

}  // namespace accelcal

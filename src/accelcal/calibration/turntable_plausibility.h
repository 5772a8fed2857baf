// What a bench turntable can be: the radius and speed an operator may state for a run. One
// check for every way a run enters the program: the wizard's answers (app/wizard/
// quantity_input.h) and the runs of a capture set or a session, screened before a fit
// (capture_screening.h), so that a radius typed in the wrong unit or swapped with the speed is
// refused, never fitted.
#pragma once

#include <string>

namespace accelcal {

// Plausible turntable radii, m, and speeds, rpm.
inline constexpr double kMinRadiusM = 0.005;
inline constexpr double kMaxRadiusM = 2.0;
inline constexpr double kMinRpm = 1.0;
inline constexpr double kMaxRpm = 3000.0;

bool IsPlausibleTurntableRadius(double radius_m);
bool IsPlausibleTurntableRpm(double rpm);

// Empty when a run's stated radius (m) and speed (rpm) are both plausible; else what is wrong,
// in words, e.g. "stated radius 120 m is not a plausible turntable radius (expected 5 mm to
// 2 m) and speed 0.1 rpm is not a plausible turntable speed (expected 1 to 3000 rpm): are the
// radius and the speed swapped?".
std::string TurntableConditionsProblem(double radius_m, double rpm);

}  // namespace accelcal

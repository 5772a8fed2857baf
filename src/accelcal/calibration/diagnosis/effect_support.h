// What the effects of the library (sensor_effects.cpp, bench_effects.cpp) share: how they look
// at a set of captures to decide whether it identifies them, the bounds of what is physically
// plausible, and the forms of their statements in bench units. Private to the diagnosis (the
// effects are reached through effect.h).
#pragma once

#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/sensor_model.h"
#include "accelcal/calibration/diagnosis/effect.h"

namespace accelcal::effects {

// "q_x", "q_y", "q_z" for stem "q".
std::string PerAxis(const char* stem, int axis);
// All three: {"q_x", "q_y", "q_z"}.
std::vector<std::string> PerAxisNames(const char* stem);

// The full scale the nonlinearity bound is taken against, m/s^2: 6 g, the widest range of the
// seed's MMA7260Q (the lab chapter's part).
inline constexpr double kFullScaleMps2 = 6.0 * 9.80665;
// The nonlinearity a sensor may show, as a fraction of full scale: the MMA7260Q datasheet's
// worst case is +-1 % of full scale (quoted in the lab chapter); accelcal allows twice that.
inline constexpr double kMaxNonlinearityFraction = 0.02;

// Number of turntable captures, and of distinct stated radii among them (1e-4 m apart).
int CountTurntable(const std::vector<FitCapture>& captures);
int CountDistinctRadii(const std::vector<FitCapture>& captures);

// Spread (max - min) of a per-capture quantity; NaN when any capture lacks it.
double SpreadOfTemperature(const std::vector<FitCapture>& captures);
double SpreadOfTime(const std::vector<FitCapture>& captures);

// True when axis j's capture means, scaled to -1..1 over their range and kept where they are
// clearly non-zero (|x| > 0.2), support the design [1, x, x^power] (power 2 or 3): its columns,
// normalized, have a smallest singular value above 5 % of the largest. Power 2 needs three
// distinct levels; power 3 needs two distinct magnitudes (+-1 alone makes x^3 = x).
bool SeesLevelsFor(const std::vector<FitCapture>& captures, int axis, int power);

// Each capture's input u = K^-1 (mean - b) through `base`, m/s^2 (the a^a of sensor_model.h).
std::vector<Eigen::Vector3d> Inputs(const std::vector<FitCapture>& captures, const SensorModel& base);

// Each capture's direction of specific force (unit vector, sensor frame) through a rough model
// made from the captures themselves (per axis: the midpoint and half-range of the static means,
// or of all means when fewer than two static captures), good to a few degrees: enough to judge
// which products of axis components a set of poses excites.
std::vector<Eigen::Vector3d> RoughDirections(const std::vector<FitCapture>& captures);

// The stated centripetal acceleration of a turntable capture, m/s^2; NaN for a static one.
double CentripetalMps2(const FitCapture& c);

// The first of `values`; NaN when there are none.
double FirstOf(std::span<const double> values);
// "<lead>x +4.0, y -2.0, z +0.0 <unit>": each of `values` times `factor`, in `unit`, with
// `decimals` digits after the point.
BenchStatement PerAxisStatement(std::string lead, std::span<const double> values, double factor, int decimals,
                                std::string unit);

}  // namespace accelcal::effects

#include "accelcal/app/turntable_run_check.h"

#include <cmath>

#include "accelcal/acquire/capture_engine/turntable_stability.h"
#include "accelcal/calibration/fit/calibration_fit.h"

namespace accelcal {
namespace {

// The rough model of the header's check 2: the static captures' fit, else all captures'.
std::optional<SensorModel> RoughModel(const std::vector<Capture>& captures, const GravitySpec& gravity) {
  FitOptions fit;
  fit.gravity = gravity;
  std::vector<FitCapture> statics, all;
  for (const Capture& c : captures) {
    if (!c.used()) continue;
    all.push_back(MakeFitCapture(c));
    if (c.kind == CaptureKind::kStatic) statics.push_back(all.back());
  }
  for (const std::vector<FitCapture>* set : {&statics, &all}) {
    if (!CheckDeterminable(*set, fit).empty()) continue;
    const FitSummary s = FitCalibration(*set, fit);
    if (s.IsUsable()) return s.Model();
  }
  return std::nullopt;
}

// The setup of a recorded run: what was stated, mounted with its up axis up (+z when not
// known), and radially outward the in-plane axis whose mean reads the most negative (the
// centripetal force points inward).
TurntableSetup SetupOf(const Capture& c, const SensorModel& rough) {
  TurntableSetup setup;
  setup.radius_m = c.radius_m;
  setup.rpm = c.rpm;
  setup.up_axis = c.up_axis ? SensorAxisVector(*c.up_axis) : Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d mean_mps2 = rough.Calibrate(c.stats().mean_counts);
  double largest = -1.0;
  for (int j = 0; j < 3; ++j) {
    if (std::fabs(setup.up_axis(j)) > 0.5 || !(std::fabs(mean_mps2(j)) > largest)) continue;
    largest = std::fabs(mean_mps2(j));
    setup.radial_axis = (mean_mps2(j) > 0.0 ? -1.0 : 1.0) * Eigen::Vector3d::Unit(j);
  }
  return setup;
}

// Check 2 alone: the options make the steadiness and tilt checks unable to fail.
std::string CentripetalMismatch(const Capture& c, const SensorModel& rough, const GravitySpec& gravity,
                                double tolerance) {
  TurntableStabilityOptions options;
  options.gravity_mps2 = gravity.gravity_mps2;
  options.centripetal_tolerance = tolerance;
  options.speed_tolerance = 1e9;
  options.max_tilt_deg = 90.0;
  const TurntableVerdict v = EvaluateTurntable(c.samples, rough, SetupOf(c, rough), options);
  return v.consistent ? std::string() : v.reason;
}

}  // namespace

void CheckTurntableRuns(std::vector<Capture>& captures, const GravitySpec& gravity,
                        const TurntableRunCheckOptions& options) {
  bool any = false;
  for (const Capture& c : captures) any = any || (c.used() && c.kind == CaptureKind::kTurntable);
  if (!any) return;
  const std::optional<SensorModel> rough = RoughModel(captures, gravity);
  if (!rough) return;  // nothing to judge the runs by; the fit's own checks remain
  TurntableStabilityOptions plan_options;
  plan_options.gravity_mps2 = gravity.gravity_mps2;
  for (Capture& c : captures) {
    if (!c.used() || c.kind != CaptureKind::kTurntable) continue;
    std::string why;
    if (options.adc_range) why = CheckTurntablePlan(SetupOf(c, *rough), *rough, *options.adc_range, plan_options);
    if (why.empty() && c.up_axis)
      why = CentripetalMismatch(c, *rough, gravity, options.centripetal_tolerance);
    if (!why.empty()) c.rejection_reason = "the stated radius or speed does not match the run: " + why;
  }
}

}  // namespace accelcal

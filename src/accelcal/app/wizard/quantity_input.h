// Values the operator types, with units: a turntable radius and speed. Each parse returns the
// value in SI (m, rpm as the bench states it) or refuses with the reason in words, e.g.
//   "12 m is not a plausible turntable radius: did you mean 12 cm?"
// Units: m for radii, rpm for speed, g for the accelerometer's range. A decimal comma ("0,12")
// reads as a point; text of blanks only is blank (IsBlank), which the wizard treats as empty.
#pragma once

#include <string>
#include <string_view>

#include "accelcal/acquire/capture_engine/turntable_stability.h"
#include "accelcal/base/capture_set.h"
#include "accelcal/base/sensor_model.h"
#include "accelcal/calibration/turntable_plausibility.h"

namespace accelcal {

struct QuantityResult {
  double value = kNaN;  // valid when error is empty
  std::string error;    // why the text was refused
  bool ok() const { return error.empty(); }
};

// The plausible radii and speeds (kMinRadiusM ... kMaxRpm) are those every turntable run is
// screened with: calibration/turntable_plausibility.h.

// True when `text` is empty or only blanks: the wizard takes the default for it, as for "".
bool IsBlank(std::string_view text);

// The field a typed value belongs to by its unit: "300 rpm" and "2 Hz" are speeds, "12 cm" a
// radius; kNone without a unit or with one of neither (each field's parse then says why).
enum class TurntableField { kNone, kRadius, kSpeed };
TurntableField FieldOfUnit(std::string_view text);

// "120 mm", "12 cm", "0.12 m", "0.12" (m), "0,12" (m). Result in m.
QuantityResult ParseRadius(std::string_view text);
// "120", "120 rpm", "2 rps", "2 Hz" (= rps), "12.57 rad/s". Result in rpm.
QuantityResult ParseRpm(std::string_view text);

// Empty when the planned run stays within the accelerometer's range: the peak specific force
// (centripetal along the radial axis, g along up) below range_g, and the ADC not clipping
// through the rough model (CheckTurntablePlan). Else the reason.
std::string CheckTurntableAgainstRange(const TurntableSetup& setup, double range_g,
                                       const SensorModel& rough_model, const AdcRange& adc_range,
                                       const TurntableStabilityOptions& options);

}  // namespace accelcal

// The turntable checks of the capture engine (acquire/capture_engine/turntable_stability.h),
// applied to turntable runs that come from a file or a session before they are fitted, so that
// `accelcal fit` refuses what the wizard would have refused while capturing:
//
// 1. The plan against the sensor's range (CheckTurntablePlan): the stated radius and speed must
//    give a specific force the ADC can hold. A run whose readings did not clip although its
//    stated conditions say they must have was not taken at those conditions. Needs the ADC
//    range (the capture set's `# adc_range_counts`, --adc-range, the procedure's).
// 2. The stated radius and speed against the measured centripetal acceleration (check 1 of
//    EvaluateTurntable), through a rough model fitted to the static captures alone (or to all
//    captures when the static ones cannot determine it). Needs the run's up axis. The tolerance
//    is wider than the live check's 10 %: a radius offset, a speed error and the size effect
//    move the centripetal part by a few % and are the diagnosis's to find; what is refused here
//    is what no effect explains (a radius typed as 0.07 for 0.05 m is 29 % off).
//
// The steadiness of the speed and the table's tilt are not judged here: the first only live
// (a recorded run's mean is what the fit sees), the second is an effect the diagnosis can find.
// A run that fails gets a rejection_reason in words and is left out of the fit.
#pragma once

#include <optional>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/capture_set.h"
#include "accelcal/base/gravity.h"

namespace accelcal {

struct TurntableRunCheckOptions {
  double centripetal_tolerance = 0.25;  // largest |measured / stated - 1| of check 2; (0, 1)
  std::optional<AdcRange> adc_range;    // check 1 runs only when known
};

// Checks every used turntable capture of `captures` as above (static captures and those
// already left out are untouched).
void CheckTurntableRuns(std::vector<Capture>& captures, const GravitySpec& gravity,
                        const TurntableRunCheckOptions& options);

}  // namespace accelcal

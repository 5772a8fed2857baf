// The certificate's "limited by" (issue 29): which uncertainty dominates the results, in words.
// From the GUM budget: each fitted parameter's largest contribution to u_c, the parameters
// grouped by it ("the offsets by the captures' noise (type A); the scales by the turntable
// radius"); the type A named for what it is (the captures' noise, or the scatter between them when
// the residuals exceed noise); then what limits the calibration beyond the noise
// (Calibration::limited_by: a settling sensor, a near-tie, a pose that moved).
#pragma once

#include <string>

#include "accelcal/calibration/calibration.h"

namespace accelcal {

// "The uncertainty is limited by ..." (one paragraph); without a budget, from the fit alone.
std::string LimitedByStatement(const Calibration& calibration);

}  // namespace accelcal

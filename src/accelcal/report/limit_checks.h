// The report's checks against the procedure's [limits] (session/procedure.h), made on the
// numbers the certificate prints (issue 27):
//  - the fit's own: captures used, residual RMS (alone and over the captures' noise);
//  - the limits on U, the expanded uncertainty (k = 2) of each parameter group (bias, scale,
//    misalignment), U from the calibration's GUM budget (type A and type B: the same U as the
//    certificate's results); a U over its limit means the calibration cannot show conformity,
//    and the check says which parts of the budget dominate and what uncertainty each would need
//    for U to come under the limit ("measure the radius to 0.09 mm or better");
//  - the tolerances on the values (a datasheet's range around the procedure's nominal model),
//    judged by the procedure's decision rule (ILAC-G8:09/2019): simple acceptance (4.2.1, the
//    value as found within the tolerance) or a guard band (4.2.2, within the tolerance narrowed
//    by w = U; a U as large as the tolerance leaves no value that could conform).
// Without a budget (a calibration file made by `accelcal fit`) U is twice the fit's 1-sigma,
// type A alone, as the certificate says; the verdict is then INCOMPLETE (completeness.h).
#pragma once

#include <string>
#include <vector>

#include "accelcal/calibration/uncertainty_budget.h"
#include "accelcal/report/report_model.h"

namespace accelcal {

// The U (k = 2 for infinite degrees of freedom) the certificate states for parameter `index`:
// the budget's, else twice the fit's 1-sigma; NaN when the parameter is held.
double CertificateExpandedUncertainty(const Calibration& cal, int index);

// Every check of `limits` on the calibration of `in` (`m` holds the fit's statistics).
std::vector<LimitCheck> CheckProcedureLimits(const ProcedureLimits& limits, const ReportInputs& in,
                                             const ReportModel& m);

// Why `p`'s U exceeds `limit` (in its own unit) and what would bring it under: its dominant
// parts with the uncertainty each would need. `to_display` turns the parameter's unit into the
// text's `display_unit` ("mrad": 1000). Empty when U is within the limit.
std::string UncertaintyRemedy(const ParameterBudget& p, double limit, double to_display,
                              const std::string& display_unit);

}  // namespace accelcal

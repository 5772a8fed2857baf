// Why a report's verdict cannot be PASS although no limit failed (report_model.h's Verdict:
// INCOMPLETE), each reason in words for the report, the certificate and the wizard's summary:
//  - what the session lacks: a capture damaged in its file, a required step skipped or whose
//    capture was left out (by a lowered noise floor or by the fit), a required identification;
//  - the equipment's identification: a certificate lists the bench's items, and a placeholder
//    id (the shipped procedures' "(example)" ids, an empty one) identifies nothing;
//  - the uncertainty the limits on U need: a budget (a calibration file of `accelcal fit` has
//    none: its U would be type A alone), and every reference quantity's uncertainty stated;
//  - which of gravity and turntable is right: the captures see only w^2 r / g, so a turntable
//    speed or radius scale found (rpm_scale, radius_offset) may be a wrong gravity. PASS then
//    needs a gravity other than the standard value, the scale corrected (adopted), and the
//    turntable's speed and radius verified (the procedure's [equipment] ruler and turntable
//    identified, with their calibration stated) with the scale found within the uncertainty they
//    verify (k = 2); otherwise both checks are named.
#pragma once

#include <string>
#include <vector>

#include "accelcal/report/report_model.h"

namespace accelcal {

// Every reason, in order; empty when nothing is missing. `checks` are the limits' (a limit on U
// makes the budget's completeness matter).
std::vector<std::string> IncompleteReasons(const ReportInputs& in, const std::vector<LimitCheck>& checks);

}  // namespace accelcal

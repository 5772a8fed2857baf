// What the technician does next when a session's verdict is not PASS (issue 27, item 7): one
// line per kind of cause, in bench words, with the command that does it where one does:
//  - a required run the fit left out: take it again (the wizard offers it on this session);
//  - a required step skipped: a finished session takes no more steps, a new session does;
//  - an identification, the equipment's ids or the uncertainty of a reference quantity missing,
//    or the gravity or the turntable in doubt: the inputs corrected by `accelcal refit` (no
//    capture taken again);
//  - a limit on U not met: what dominates U measured better, then `accelcal refit`;
//  - a value outside its tolerance: the device does not conform (or U is too large to show it);
//  - the fit's own checks: the captures do not agree with one model: the bench checked and a
//    new session.
// Empty for PASS and for a procedure that states no limits and lacks nothing.
#pragma once

#include <string>
#include <vector>

#include "accelcal/report/report_model.h"

namespace accelcal {

// `in` and `verdict` are the report's (BuildReportModel(in)); `session` names the session in the
// commands ("accelcal refit SESSION"); `left_out_by_fit`: the ids of the required steps whose
// capture the fit left out (CalibrationSteps::left_out_by_fit).
std::vector<std::string> NextSteps(const ReportInputs& in, const ReportModel& verdict, const std::string& session,
                                   const std::vector<std::string>& left_out_by_fit);

}  // namespace accelcal

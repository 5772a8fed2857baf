// What a wizard session lacks that its procedure asked for, gathered for the report
// (session/session_gaps.h): the steps skipped, the steps whose capture was left out after it was
// accepted (judged again against a lowered noise floor, and not captured again, or left out by
// the fit: a turntable run that disagrees with the other captures), and the identification the
// procedure requires but the welcome left empty.
#pragma once

#include "accelcal/app/wizard/session_model.h"
#include "accelcal/calibration/calibration.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_gaps.h"
#include "accelcal/session/session_inputs.h"  // kWelcomeStepId

namespace accelcal {

SessionGaps CollectSessionGaps(const Procedure& procedure, const SessionModel& model);

// The capture steps whose current capture the calibration `cal` leaves out (its screening, a
// run that disagrees with the others: calibration_pipeline.h), added to `gaps`, each named by
// what tells it apart from its like (a turntable run by its radius and speed, as entered).
// Returns their step ids, in the procedure's order.
std::vector<std::string> AddLeftOutByTheFit(const Procedure& procedure, const SessionModel& model,
                                            const Calibration& cal, SessionGaps* gaps);

}  // namespace accelcal

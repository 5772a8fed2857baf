// What a wizard session lacks that its procedure asked for, gathered for the report
// (session/session_gaps.h): the steps skipped, the steps whose capture was left out after it was
// accepted (judged again against a lowered noise floor, and not captured again), and the
// identification the procedure requires but the welcome left empty.
#pragma once

#include "accelcal/app/wizard/session_model.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_gaps.h"

namespace accelcal {

// The welcome's pseudo step: its inputs are the session's identification and gravity.
inline constexpr const char* kWelcomeStepId = "welcome";

SessionGaps CollectSessionGaps(const Procedure& procedure, const SessionModel& model);

}  // namespace accelcal

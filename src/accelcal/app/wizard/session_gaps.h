// What a wizard session lacks that its procedure asked for, gathered for the report
// (session/session_gaps.h): the steps skipped, the steps whose capture was left out after it was
// accepted (judged again against a lowered noise floor, and not captured again), and the
// identification the procedure requires but the welcome left empty.
#pragma once

#include "accelcal/app/wizard/session_model.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_gaps.h"
#include "accelcal/session/session_inputs.h"  // kWelcomeStepId

namespace accelcal {

SessionGaps CollectSessionGaps(const Procedure& procedure, const SessionModel& model);

}  // namespace accelcal

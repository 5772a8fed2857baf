// What a resumed session already holds, for the technician: one line per step in the
// procedure's order, with its title ("+x up: done (capture 5)", "Turntable x radial, z up at
// 100 mm: skipped"), never the internal step ids.
#pragma once

#include <string>
#include <vector>

#include "accelcal/app/wizard/session_model.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

// The step's title as the technician reads it (its kind's display title, step_registry.h): a
// turntable step whose title is only its mounting (several steps share it) gets "Turntable" and
// its radius ("Turntable x radial, z up at 100 mm").
std::string StepDisplayTitle(const ProcedureStep& step);

// The summary's lines (indented by two spaces): the welcome, then each step of `procedure` that
// has something recorded (done, skipped, captured, left out, partly recorded), in the procedure's
// order; steps not reached yet are not listed. `welcome_id` is the welcome's journal step id.
std::vector<std::string> ResumeSummaryLines(const Procedure& procedure, const SessionModel& model,
                                            const std::string& welcome_id);

}  // namespace accelcal

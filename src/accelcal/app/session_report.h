// The report of a session file as `accelcal report SESSION` shows it, for every command that
// renders one (report, lab publish): the journal's inputs (report_inputs.h) with the session's
// device, operator, date, name, procedure and source, the lab's certificate number once the
// session is published, and the limits and equipment of its procedure.
#pragma once

#include <string>

#include "accelcal/report/report_model.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_store.h"

namespace accelcal {

// The report inputs of `store`. Throws accelcal::Error when it has no calibration (saying what
// it holds instead). The limits and equipment are those of the procedure at
// `default_procedure_path` when the session ran it (by title); none otherwise (a missing file
// too: the report then says no limits were stated).
ReportInputs ReportInputsOfSession(const SessionStore& store, const std::string& default_procedure_path);

// The limits, equipment (as the session's welcome edited it) and nominal zero-g level of
// `procedure`, into `in` (a procedure named on the command line).
void ApplyProcedureToReport(const Procedure& procedure, ReportInputs* in);

}  // namespace accelcal

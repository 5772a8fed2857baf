// What a report of a session needs, read from its journal: the recorded calibration (strictly
// read: InputError naming the session when damaged; Error when there is none yet), its
// intact captures (and what is damaged in the file, ReportInputs::damaged_captures),
// device/operator/place from the inputs, and the result's "allan"/"noise" analyses.
// Limits and the rest of the meta are the caller's.
#pragma once

#include <string>

#include "accelcal/report/report_model.h"
#include "accelcal/session/session_journal.h"

namespace accelcal {

ReportInputs ReportInputsFromJournal(const SessionJournal& journal, const std::string& source_name);

}  // namespace accelcal

#include "accelcal/app/report_inputs.h"

#include <fmt/core.h>

#include "accelcal/app/refit_session.h"
#include "accelcal/base/error.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/session_result_file.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {

ReportInputs ReportInputsFromJournal(const SessionJournal& journal, const std::string& source_name) {
  const std::optional<std::string> result = journal.Result();
  if (!result) throw Error(fmt::format("session {} has no calibration yet", source_name));
  ReportInputs in;
  in.calibration = CalibrationFromJsonText(*result, source_name);
  // Superseded captures (taken again) stay in the session, out of the report.
  for (const JournalCapture& c : CurrentCaptures(journal.Captures()))
    in.captures.push_back(ReportStatsOf(c.capture));
  for (const DamagedCapture& d : journal.DamagedCaptures()) in.damaged_captures.push_back(d.Describe());
  const SessionInputs inputs = journal.Inputs();
  FillMetaFromInputs(inputs, &in.meta);
  in.bench_time = BenchTimeFromInputs(inputs);
  if (std::optional<std::string> equipment = ReadWelcomeAnswers(inputs).equipment)
    in.equipment_answer = std::move(*equipment);
  ReadAnalysesFromResultText(*result, source_name, &in);
  in.meta.history = SessionHistory(journal, journal.ResultCount() - 1);
  return in;
}

}  // namespace accelcal

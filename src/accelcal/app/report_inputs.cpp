#include "accelcal/app/report_inputs.h"

#include <fmt/core.h>

#include "accelcal/app/refit_session.h"
#include "accelcal/base/error.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/session_result_file.h"

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
  FillMetaFromInputs(journal.Inputs(), &in.meta);
  // (Inputs() returns a copy: hold it while its iterators are used.)
  const std::map<std::string, std::map<std::string, std::string>> inputs = journal.Inputs();
  if (const auto welcome = inputs.find("welcome"); welcome != inputs.end())
    if (const auto answer = welcome->second.find("equipment"); answer != welcome->second.end())
      in.equipment_answer = answer->second;
  ReadAnalysesFromResultText(*result, source_name, &in);
  in.meta.history = SessionHistory(journal, journal.ResultCount() - 1);
  return in;
}

}  // namespace accelcal

// What the wizard writes besides its journal: the report files and the Allan file, behind one
// interface, so that the engine (a state machine) writes no file itself.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accelcal/analysis/record_analysis.h"
#include "accelcal/report/report_model.h"

namespace accelcal {

class WizardOutputs {
 public:
  virtual ~WizardOutputs() = default;
  // The report of a finished calibration; returns the paths written. Throws accelcal::Error.
  virtual std::vector<std::string> WriteReports(const ReportInputs& inputs) = 0;
  // The report files an earlier run wrote and that are still there (a resumed session's
  // summary names them); none by default.
  virtual std::vector<std::string> ReportPaths() const { return {}; }
  // The Allan analysis of a record; returns the path written. Throws accelcal::Error.
  virtual std::string WriteAllan(const RecordAnalysis& analysis, const std::string& source,
                                 double drift_window_s) = 0;
};

// Writes beside `session_path`: SESSION.report.html, SESSION.report.txt, SESSION.allan.json
// (report_files.h).
std::unique_ptr<WizardOutputs> MakeOutputsBesideSession(std::string session_path);

}  // namespace accelcal

// What a report of a calibration file or a session says beside the calibration (`accelcal
// report`, `accelcal lab publish`): for a session, its captures and who, when, where and how (its
// device, operator, date, name, path, procedure, source) and the lab's certificate number once it
// is published; the procedure's limits that decide the verdict, its equipment
// and nominal zero-g level; the Allan and noise analyses. The calibration and the errors are
// calibration_input.h's.
#pragma once

#include <string>

#include "accelcal/report/report_model.h"

namespace accelcal {

struct ReportRequest {
  std::string input;           // a calibration file, a session file or a session's name
  // The procedure whose [limits] decide pass/fail and whose [equipment] the certificate lists.
  // Empty: `default_procedure_path`'s, when the session ran that procedure (same title); a
  // calibration file alone states none.
  std::string procedure_path;
  std::string default_procedure_path;  // the shipped seed procedure (the front end knows where)
  std::string allan_path;      // an Allan analysis (allan.json) to include; empty: the input's
  std::string noise_path;      // a noise analysis (noise.json) to include; empty: the input's
  // Which sensor of a several-sensor session (`--sensor N`, here N - 1): its captures, its
  // calibration, its serial as the device (sensor_journal_view.h). 0 for any other input.
  int sensor = 0;
};

// The report's inputs from `input` alone: the calibration and the analyses and session gaps
// recorded beside it; from a session, its captures and meta too. Throws accelcal::Error (an
// InputError for a damaged file) naming what could not be read.
ReportInputs ReportInputsOf(const std::string& input, int sensor = 0);

// ReportInputsOf(request.input), with the procedure's limits and equipment and the analyses
// given. Throws as ReportInputsOf, and naming the procedure or analysis file that cannot be read.
ReportInputs ReportInputsFor(const ReportRequest& request);

}  // namespace accelcal

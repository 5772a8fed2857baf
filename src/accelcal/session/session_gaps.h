// What a wizard session lacks that its procedure asked for: the steps skipped or whose capture
// was left out (by a lowered noise floor or by the fit), the identification left empty, the
// gravity the data cannot tell from a bench effect. Collected by the wizard (app/wizard/session_gaps.h), recorded beside the session's
// calibration (io/session_result_file.h) and judged by the report (report/report_model.h: a
// required gap keeps the verdict from PASS). A calibration file alone knows nothing of it.
#pragma once

#include <string>
#include <vector>

namespace accelcal {

// The report lists every entry; a required one keeps the verdict from PASS.
struct SessionGaps {
  struct Step {
    std::string id;       // the procedure's step id
    std::string title;    // as shown to the operator
    std::string why;      // "skipped", "its capture was left out: not still: ..."
    bool required = true;
  };
  std::vector<Step> steps;                  // in procedure order
  std::vector<std::string> identification;  // required and empty: "device serial", "operator"
  // The diagnosis found a turntable speed or radius scale (adopted or declined: the base model
  // then carries the same error in its scales): its note (GravityAmbiguityNote), else empty.
  std::string gravity_ambiguity;
};

}  // namespace accelcal

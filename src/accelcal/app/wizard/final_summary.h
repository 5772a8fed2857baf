// The wizard's last word: the verdict (PASS / FAIL / INCOMPLETE / NO LIMITS STATED), the limits
// failed with why and what would bring them within, what is missing, the calibration's headline
// numbers with their expanded uncertainty U (k = 2) as the certificate states and rounds them
// (bias, scale, misalignment; residual RMS) and the paths of the report files; the fit's 1-sigma
// (type A) apart, in the details. Shown on the final screen, left
// on the terminal after the TUI exits and printed at the end of line mode; built from the report
// model (report/report_model.h), so it never says other numbers than the report.
#pragma once

#include <string>
#include <vector>

#include "accelcal/report/report_model.h"

namespace accelcal {

struct FinalSummary {
  Verdict verdict = Verdict::kNoLimits;
  // The last screen's first words, from the verdict: "Calibration complete." only for a PASS;
  // a FAIL or an INCOMPLETE says so and points at the next steps in `lines`.
  std::string ending;
  // "Verdict: PASS", then the failed limits and what is missing, the next steps, the headline
  // numbers +- U, the report paths (report paths aside, within 80 columns).
  std::vector<std::string> lines;
  // The statistics behind them: the headline numbers +- the fit's 1-sigma (type A), and how
  // each limit was judged.
  std::vector<std::string> details;
};

// `next_steps`: what to do when the verdict is not PASS (next_steps.h), listed after what failed.
FinalSummary BuildFinalSummary(const ReportModel& report, const std::vector<std::string>& report_paths,
                               const std::vector<std::string>& next_steps = {});

// The ending of a session whose report `verdict` was made in an earlier run (opened again with
// nothing left to do).
std::string EarlierEnding(Verdict verdict);

}  // namespace accelcal

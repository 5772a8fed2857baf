// The bench time of a session, as its report states it (issue 32: the technician's time): the
// plan the wizard ran by (app/wizard/bench_plan.h) and what the captures took, each split into
// capture, settling and handling; and, per parameter, the expanded uncertainty U (k = 2) the
// plan predicted beside the one the calibration reached (its budget's).
//
// Read from the journal's inputs (session_inputs.h, bench_key), so `accelcal report` of a
// session says the same as the wizard's own report. Handling on the virtual bench is the
// procedure's handling model; on a real bench the session's clock.
//
// Units: s; U in each parameter's unit (counts, counts per m/s^2, rad).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/calibration/uncertainty_budget.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {

struct BenchSeconds {
  double capture_s = 0.0;
  double settle_s = 0.0;
  double handling_s = 0.0;
  double TotalS() const { return capture_s + settle_s + handling_s; }
};

struct BenchParameterU {
  std::string name;            // "bias_x", ...
  double target = kNaN;        // U wanted (NaN: none)
  double planned = kNaN;       // U the plan predicted
  double reached = kNaN;       // U of the calibration's budget (NaN: no budget)
};

struct ReportBenchTime {
  std::string planned_by;      // "target" (the procedure's [target]) or "fixed"
  BenchSeconds planned;
  BenchSeconds spent;
  int captures = 0;            // the captures whose time is in `spent`
  std::vector<BenchParameterU> parameters;  // the nine, ParameterIndex order
};

// The bench time recorded in a session's inputs; nullopt when it recorded none (a session from
// before the plan, a calibration file alone).
std::optional<ReportBenchTime> BenchTimeFromInputs(const SessionInputs& inputs);

// The reached U of each parameter from `budget` (left NaN where it has none).
void FillReachedU(const UncertaintyBudget& budget, ReportBenchTime* bench);

// The report's lines: "Bench time: 6 min 10 s spent (planned 6 min 5 s): capture 72 s, settling
// 40 s, handling 258 s", then the planned and reached U of each parameter with a target.
std::vector<std::string> BenchTimeLines(const ReportBenchTime& bench);

}  // namespace accelcal

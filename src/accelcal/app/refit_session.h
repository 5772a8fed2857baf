// Correcting a finished session after the fact (issue 27, item 5): `accelcal refit SESSION`
// with a corrected gravity, equipment or identification. The captures are fitted again by the
// wizard's own report step (CalibrationSteps: the same pipeline, gaps, budget and verdict), the
// new calibration is recorded as the session's result, and the report files beside the session
// are written again. Nothing is replaced silently: the earlier results stay in the session (its
// `results` table is a history; the latest is the session's result), the welcome's inputs take
// the corrected values, and a step "refit N" records when and what changed from what, which
// `accelcal report` lists.
//
// Also here: the flags a wizard run on an existing session does not use (its welcome already
// recorded them), named so that they are never silently ignored.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/app/wizard/final_summary.h"
#include "accelcal/base/gravity.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_journal.h"

namespace accelcal {

struct RefitRequest {
  std::optional<GravitySpec> gravity;           // the corrected local gravity
  std::optional<std::string> equipment_answer;  // edits, as at the welcome ("ruler id RUL-7 u 0.05 cal C-1")
  std::optional<std::string> device;            // the device's serial
  std::optional<std::string> operator_name;
  std::optional<std::string> place;
  std::string session_name;   // the calibration's source and the report's session name
  std::string report_beside;  // non-empty: the report files are written beside this session file
  std::string source;         // the session's sample source (the report says it)
  std::string now_utc;        // when (ISO 8601), recorded with the changes
};

struct RefitOutcome {
  std::vector<std::string> changes;  // "gravity: standard -> 9.78030 +- 0.00001"; may be empty
  std::string refit_step;            // the journal step that records them ("refit 1")
  int earlier_results = 0;           // results the session held before this one (kept)
  FinalSummary summary;              // the verdict and the headline numbers, as the wizard says them
};

// Refits the session of `journal` (opened for writing; it must hold a result: a calibration
// was recorded) with `procedure` (the one it ran). Throws accelcal::Error with the reason for
// a session without a result, a refused value (as the welcome refuses it: a standard gravity a
// procedure refuses, an empty serial it requires, an equipment answer it cannot read), or an
// unusable fit (nothing is recorded then).
RefitOutcome RefitSession(SessionJournal& journal, const Procedure& procedure, const RefitRequest& request);

// `accelcal refit`: the session `input` names (a file, or a name in the default folder; opened by
// app/calibration_input.h's OpenSessionToChange: a calibration file is refused), refitted with
// the procedure it ran, `procedure_path`'s (refused when the session ran another), else
// `default_procedure_path`'s when it is that one (else an Error asks for --procedure), with
// `corrections` (its gravity, equipment and identification; the session's name, source, the
// report beside it and the time are filled here). Throws as RefitSession.
struct RefitFileRequest {
  std::string input;
  std::string procedure_path;          // empty: the default, when the session ran it
  std::string default_procedure_path;  // the shipped full procedure
  RefitRequest corrections;
};
struct RefitFileOutcome {
  std::string path;  // the session file refitted
  RefitOutcome refit;
};
RefitFileOutcome RefitSessionFile(const RefitFileRequest& request);

// What the session's history says: each refit with what it changed, and (when
// `earlier_results` > 0) that the earlier calibrations are kept ("1 earlier calibration is kept
// in the session; this is the latest"); empty for a session fitted once.
std::vector<std::string> SessionHistory(const SessionJournal& journal, int earlier_results);

// The wizard's flags that a run on this (existing) session does not use, each named with why
// and what to do instead: "--latitude 0 ignored: this session's gravity was recorded at its
// welcome (standard); to calibrate it with another: accelcal refit SESSION --latitude 0" (",
// once the session is finished" when it has no calibration yet). `gravity_flag` and
// `place_flag` as given ("" when not).
std::vector<std::string> UnusedResumeFlags(const SessionJournal& journal, const std::string& session,
                                           const std::string& gravity_flag, const std::string& place_flag);

}  // namespace accelcal

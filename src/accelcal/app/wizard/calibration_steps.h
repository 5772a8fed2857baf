// The wizard's steps that compute rather than capture: the fit, the diagnosis, the report and
// the analysis of a record. Each runs on the session model (the accepted captures, the record
// chunks) through the shared pipeline (app/calibration_pipeline.h), and says what to show.
// Files are written only through WizardOutputs; the session's result through the model.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/capture_engine/noise_floor.h"
#include "accelcal/app/calibration_pipeline.h"
#include "accelcal/app/wizard/final_summary.h"
#include "accelcal/app/wizard/session_model.h"
#include "accelcal/app/wizard/wizard_outputs.h"
#include "accelcal/base/gravity.h"
#include "accelcal/report/report_model.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

// What a step has to say: its text, and what went wrong (empty when nothing) with what to do.
struct StepOutcome {
  std::vector<std::string> lines;
  // The statistics behind `lines`, shown on request (the diagnosis's BIC / AICc / LOO tables);
  // empty when the step has none.
  std::vector<std::string> details;
  std::string problem;
  std::string hint;
};

// The pipeline's request as the wizard's fit makes it, without the captures: the session's
// `gravity`, its `equipment` (the budget's type B inputs), the procedure's ADC range, and the
// static captures judged again against a `lowered` noise floor (nullopt: as judged live). The
// fixture's end (app/fixture/fixture_finish.h) calibrates every sensor from the same request.
CalibrationRequest WizardCalibrationRequest(const Procedure& procedure, const GravitySpec& gravity,
                                            const std::vector<EquipmentItem>& equipment,
                                            const std::optional<NoiseFloor>& lowered,
                                            std::string source_name);

class CalibrationSteps {
 public:
  // Borrows `procedure`, `model` and `outputs` (nullable: no file written); all must outlive
  // this object.
  CalibrationSteps(const Procedure& procedure, SessionModel& model, GravitySpec gravity,
                   std::string session_name, WizardOutputs* outputs);

  // The fit step: the pipeline over the accepted captures, the base fit's report.
  StepOutcome Fit();
  // The diagnosis step: the pipeline's diagnosis (run again when the captures changed).
  StepOutcome Diagnosis();
  // The report step: the calibration of the chosen model recorded as the session's result with
  // the session's `gaps` beside it, the verdict said, and the report files written (through
  // the outputs) with `meta`.
  StepOutcome Report(bool adopt_effects, const ReportMeta& meta, const SessionGaps& gaps);
  // A session resumed after its report step: the final summary (final_summary()) computed again
  // from the journal, exactly as Report computed it, with the report files already written;
  // records nothing and writes no file.
  void Recap(bool adopt_effects, const ReportMeta& meta, const SessionGaps& gaps);
  // The analysis step `step` of an earlier record; `outcome` gets its figures in one line.
  StepOutcome Analysis(const ProcedureStep& step, std::string* outcome);

  // The verdict and headline numbers of the last Report (final_summary.h); nullptr before one.
  const FinalSummary* final_summary() const { return final_summary_ ? &*final_summary_ : nullptr; }
  // The required capture steps whose capture the last Report's (or Recap's) fit left out, in the
  // procedure's order: the runs to offer to take again.
  const std::vector<std::string>& left_out_by_fit() const { return left_out_by_fit_; }

  // The current pipeline outcome (after Fit or Diagnosis); nullptr before.
  const CalibrationOutcome* outcome() const { return outcome_ ? &*outcome_ : nullptr; }

  // The session's gravity (the welcome's answer), for the runs from now on.
  void set_gravity(const GravitySpec& gravity);
  // A noise floor lowered during the session: the static captures are judged again against it
  // (those that fail are left out with the reason); nullopt: as they were judged live.
  void set_noise_floor(const std::optional<NoiseFloor>& lowered);
  // The bench's equipment (the procedure's, as edited at the welcome): the uncertainty
  // budget's type B inputs, and the report's equipment list.
  void set_equipment(std::vector<EquipmentItem> equipment);
  const std::vector<EquipmentItem>& equipment() const { return equipment_; }

 private:
  const CalibrationOutcome& Run();
  // The session's gaps for the calibration `cal` of `o`: `session_gaps` with the captures the
  // fit left out (the required ones kept in left_out_by_fit_) and the gravity ambiguity of what
  // the diagnosis found (adopted or not).
  SessionGaps GapsOf(const CalibrationOutcome& o, const Calibration& cal, const SessionGaps& session_gaps);
  // What the report of `cal` is made from: the session's captures, inputs, limits, equipment.
  ReportInputs Inputs(const Calibration& cal, const ReportMeta& meta, const SessionGaps& gaps) const;

  const Procedure& procedure_;  // borrowed
  SessionModel& model_;         // borrowed
  GravitySpec gravity_;
  std::string session_name_;
  WizardOutputs* outputs_;      // borrowed, nullable
  std::optional<CalibrationOutcome> outcome_;
  size_t outcome_captures_ = 0;  // the number of accepted captures outcome_ was computed from
  std::optional<NoiseFloor> lowered_floor_;
  std::optional<FinalSummary> final_summary_;
  std::vector<std::string> left_out_by_fit_;
  std::vector<EquipmentItem> equipment_;  // the procedure's until set_equipment
};

}  // namespace accelcal

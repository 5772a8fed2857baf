// The calibration pipeline, one for every front end: the captures (a capture set, a recording's
// static intervals, a wizard session's accepted captures) are screened (too short, NaN,
// clipped, a turntable radius or speed no bench has; optionally the offline stillness check),
// the turntable runs checked against their stated radius and speed (turntable_run_check.h), the
// used ones fitted, the diagnosis run (find the effect the model lacks, add it, before and
// after), a capture that disagrees with all the others left out or the fit refused
// (disagreeing_captures.h), and the calibration made from the chosen model. `accelcal fit` and
// the wizard's fit, diagnosis and report steps all run it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/capture_engine/offline_stability.h"
#include "accelcal/app/disagreeing_captures.h"
#include "accelcal/app/turntable_run_check.h"
#include "accelcal/base/capture.h"
#include "accelcal/base/gravity.h"
#include "accelcal/calibration/calibration.h"
#include "accelcal/calibration/capture_screening.h"
#include "accelcal/calibration/diagnosis/diagnosis.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/calibration/near_tie.h"
#include "accelcal/calibration/settling.h"

namespace accelcal {

struct CalibrationRequest {
  std::vector<Capture> captures;      // all of them; screening decides which are used
  std::string source_name;            // what they came from (the calibration's "source")
  GravitySpec gravity;
  ScreeningOptions screening;
  // Capture sets read from files: judge each static capture's stillness offline (the wizard's
  // captures were judged live by the capture engine).
  std::optional<OfflineStabilityOptions> stability;
  bool diagnose = true;               // false: the base model alone (no effect looked for)
  DiagnosisOptions diagnosis;         // max_effects is set to 0 when !diagnose
  // What the captures' readings are in (counts, or a logger's converted unit taken as counts):
  // recorded in the calibration so that apply reads later readings the same way.
  ReadingUnit reading_unit;
  // The turntable runs against their stated conditions (adc_range: screening's).
  bool check_turntable_runs = true;
  double turntable_centripetal_tolerance = TurntableRunCheckOptions{}.centripetal_tolerance;
  DisagreementOptions disagreement;   // refuse is set to false when !diagnose
  // Captures still settling after their change of pose: their settled readings are used
  // (calibration/settling.h); nullopt: not looked for.
  std::optional<SettlingOptions> settling = SettlingOptions{};
  // The reference quantities' standard uncertainties (type B): when given, the calibration
  // carries its uncertainty budget (calibration/uncertainty_budget.h). The gravity's is taken
  // from `gravity` when this leaves it NaN.
  std::optional<ReferenceUncertainties> references;
};

struct CalibrationOutcome {
  std::vector<Capture> captures;      // as screened: rejection_reason says why one is left out
  GravitySpec gravity;
  std::string source_name;
  ReadingUnit reading_unit;
  bool diagnosed = false;
  DiagnosisReport diagnosis;          // base fit, adopted effects, final fit, stages
  std::optional<ReferenceUncertainties> references;  // the request's (gravity's filled in)
  SettlingFinding settling;           // detected: the captures' settled readings were used
  // Effects the captures can barely tell from the adopted ones (near_tie.h): the final fit's
  // uncertainty includes each choice.
  std::vector<NearTie> near_ties;

  // The base fit is usable (there is a calibration).
  bool usable() const { return diagnosis.base.IsUsable(); }
  // The fit that `adopt_effects` chooses: the final one (with the adopted effects) or the base.
  const FitSummary& Fit(bool adopt_effects) const;
  // The calibration of that fit (usable() must be true), with its uncertainty budget when the
  // request gave the references.
  Calibration MakeCalibration(bool adopt_effects) const;
};

// Throws accelcal::Error for invalid options; an unusable set comes back with the reason in
// diagnosis.base.message.
CalibrationOutcome CalibrateCaptures(CalibrationRequest request);

}  // namespace accelcal

#include "accelcal/app/calibration_pipeline.h"

#include <cmath>

#include "accelcal/base/error.h"
#include "accelcal/calibration/calibration_budget.h"
#include "accelcal/calibration/excess_scatter.h"
#include "accelcal/calibration/pose_repeat.h"

namespace accelcal {

const FitSummary& CalibrationOutcome::Fit(bool adopt_effects) const {
  return adopt_effects && !diagnosis.adopted.empty() ? diagnosis.final_fit : diagnosis.base;
}

Calibration CalibrationOutcome::MakeCalibration(bool adopt_effects) const {
  Calibration cal = accelcal::MakeCalibration(diagnosis, adopt_effects, gravity, captures, source_name);
  if (cal.diagnosis) cal.diagnosis->ran = diagnosed;
  cal.reading_unit = reading_unit;
  if (settling.detected) cal.limited_by.insert(cal.limited_by.begin(), {"settling", SettlingWords(settling)});
  if (adopt_effects && !diagnosis.adopted.empty())
    for (const NearTie& t : near_ties) cal.limited_by.push_back({"near_tie", NearTieWords(t)});
  // A pose taken again (a repeat step) that moved beyond noise, which the fit does not explain.
  if (!diagnosis.consistent)
    for (const PoseRepeat& r : FindPoseRepeats(captures, cal.model))
      if (r.beyond_noise) cal.limited_by.push_back({"reference_drift", PoseRepeatLimitWords(r)});
  if (references)
    cal.budget = MakeCalibrationBudget(diagnosis, adopt_effects, captures, gravity.gravity_mps2, *references);
  return cal;
}

CalibrationOutcome CalibrateCaptures(CalibrationRequest request) {
  if (std::string e = request.screening.Validate(); !e.empty()) throw Error(e);
  CalibrationOutcome out;
  out.gravity = request.gravity;
  out.source_name = request.source_name;
  out.reading_unit = request.reading_unit;
  out.diagnosed = request.diagnose;
  if (request.references) {
    if (std::string e = request.references->Validate(); !e.empty()) throw Error(e);
    out.references = request.references;
    if (std::isnan(out.references->gravity_mps2)) out.references->gravity_mps2 = request.gravity.sigma_mps2;
  }
  out.captures = std::move(request.captures);
  ScreenCaptures(out.captures, request.screening);
  if (request.stability) ScreenStaticStability(out.captures, *request.stability);
  if (request.check_turntable_runs)
    CheckTurntableRuns(out.captures, request.gravity,
                       {request.turntable_centripetal_tolerance, request.screening.adc_range});
  if (request.settling) out.settling = HandleSettling(out.captures, *request.settling);

  FitOptions fit;
  fit.gravity = request.gravity;
  std::vector<FitCapture> used;
  for (const Capture& c : out.captures)
    if (c.used()) used.push_back(MakeFitCapture(c));
  DiagnosisOptions diagnosis = request.diagnosis;
  if (!request.diagnose) diagnosis.max_effects = 0;
  out.diagnosis = Diagnose(used, fit, diagnosis);
  DisagreementOptions disagreement = request.disagreement;
  if (!request.diagnose) disagreement.refuse = false;
  ResolveDisagreeingCaptures(out.captures, fit, diagnosis, disagreement, &out.diagnosis);
  ApplyExcessScatter(out.captures, diagnosis.consistency_p, &out.diagnosis);
  if (request.diagnose && !out.diagnosis.adopted.empty()) {
    out.near_ties = FindNearTies(out.diagnosis, CapturesOfFit(out.diagnosis.final_fit, out.captures), fit);
    WidenForNearTies(out.near_ties, &out.diagnosis.final_fit);
    if (!out.diagnosis.stages.empty()) out.diagnosis.stages.back() = out.diagnosis.final_fit;
  }
  return out;
}

}  // namespace accelcal

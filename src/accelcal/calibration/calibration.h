// A calibration, typed: the final model's nine parameters with their 1-sigma, the local gravity
// it was fitted with, the fit's statistics, the adopted effects (their parameters from the final
// fit, never from the round that adopted them), and every capture with its residual under each
// stage of the model (base, then after each adopted effect).
//
// This is what travels inside the program (apply, reports, exports, history); JSON is only its
// file form (io/calibration_file.h). Units: SI except where a name says counts.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/base/gravity.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/base/sensor_model.h"
#include "accelcal/calibration/fit/fit_summary.h"
#include "accelcal/calibration/uncertainty_budget.h"

namespace accelcal {

struct DiagnosisReport;

// One capture as a calibration lists it: whether the fit used it (and why not), its residual.
struct CalibrationCapture {
  int id = 0;
  CaptureKind kind = CaptureKind::kStatic;
  std::string label;
  bool used = true;
  std::string reason;                 // why it was left out; empty when used
  long n_samples = 0;
  double residual_mps2 = kNaN;        // under the final model; NaN when not used
  double reference_mps2 = kNaN;       // |f| it should show, m/s^2
  double sigma_mps2 = kNaN;           // 1-sigma of |a^p| from its own noise
  double radius_m = kNaN;
  double rpm = kNaN;
  double t_start_s = kNaN;
  double t_end_s = kNaN;
  Eigen::Vector3d mean_counts = Eigen::Vector3d::Constant(kNaN);
  // Its residual under each stage of Calibration::stages, m/s^2 (NaN when not used); empty when
  // the stages are not known (a file written by an older version).
  std::vector<double> stage_residuals_mps2;
};

// One parameter of an adopted effect, from the final fit.
struct EffectParameter {
  std::string name;   // "q_x", "dr", ...
  std::string unit;   // "counts/(m/s^2)^2", "m", ...
  double value = kNaN;
  double sigma = kNaN;  // 1-sigma
};

struct CalibrationEffect {
  std::string name;   // as in the effect library ("radius_offset", ...)
  std::vector<EffectParameter> parameters;
  double rms_before_mps2 = kNaN;   // residual RMS before and after it was adopted
  double rms_after_mps2 = kNaN;
  double chi2_per_dof_before = kNaN;
  double chi2_per_dof_after = kNaN;
  bool corrects_readings = false;  // a property of the sensor, applied to every reading
  std::string evidence;            // in words

  // The parameter called `name`; nullptr when there is none.
  const EffectParameter* Find(std::string_view parameter) const;
};

// Where the effects' temperatures and times are taken from (their means over the captures used).
struct EffectReference {
  double temp_c = kNaN;
  double t_s = kNaN;
};

struct FitStatistics {
  FitTermination termination = FitTermination::kNotRun;
  int captures_used = 0;
  int dof = 0;
  double chi2 = kNaN;
  double chi2_per_dof = kNaN;      // NaN without degrees of freedom
  double uncertainty_scale = kNaN; // sqrt(max(1, chi2/dof)) applied to the sigmas
  double condition_number = kNaN;
  // The most correlated pair of parameters, by name; empty names when not known.
  std::string most_correlated_first, most_correlated_second;
  double most_correlated_rho = kNaN;
  std::string optimizer;           // in words
  std::vector<std::string> warnings;
  // Set when the uncertainties come from the scatter between the captures (the residuals exceed
  // their noise and no effect explains them): fit/scatter_uncertainty.h. Then uncertainty_scale
  // is 1 and each 1-sigma is already the standard deviation of its t-distribution.
  std::optional<ScatterModel> scatter;
};

// What limits a calibration beyond its captures' own noise (issue 29), for the verdict and the
// certificate: the uncertainty taken from the scatter between the captures, captures that were
// still settling, a choice between two effects these captures cannot tell apart, a reference pose
// that moved over the session.
struct UncertaintyLimit {
  std::string kind;   // "scatter", "settling", "near_tie", "reference_drift"
  std::string words;  // one sentence in plain words ("the calibration is limited by ...")
};

// What the diagnosis concluded (absent when it did not run).
struct DiagnosisOutcome {
  bool ran = false;
  double base_residual_rms_mps2 = kNaN;
  double noise_rms_mps2 = kNaN;    // RMS of the captures' own sigma: what noise explains
  bool consistent_with_noise = false;
  std::string conclusion;
};

// A stage of the model: the base model, then after each adopted effect.
struct ModelStage {
  std::string name;                // "base model", "+ radius_offset", ...
  double rms_mps2 = kNaN;
};

// One of the nine parameters held at a value instead of fitted (a reduced model: the captures
// did not determine it, e.g. the misalignment from six faces).
struct HeldMark {
  std::string name;    // ParameterName(): "a_yz", ...
  double value = 0.0;  // held at, in its unit (the model carries it too)
  std::string reason;  // why, and what to capture to determine it
};

struct Calibration {
  SensorModel model;
  SensorModel uncertainty;         // 1-sigma of each parameter, same fields; NaN when held
  std::vector<HeldMark> held;      // parameters held, not fitted (empty: all nine fitted)
  // What the readings were in: counts, or a logger's m/s^2 or g taken as counts of a fraction of
  // that unit (sample_format.h); apply converts readings the same way.
  ReadingUnit reading_unit;
  GravitySpec gravity;
  double residual_rms_mps2 = kNaN;
  double residual_max_abs_mps2 = kNaN;
  std::string source;              // what was fitted (file or session name)
  FitStatistics fit;
  std::optional<DiagnosisOutcome> diagnosis;
  EffectReference reference;
  std::vector<CalibrationEffect> effects;  // adopted, in order; empty for the base model
  std::vector<ModelStage> stages;          // base first; empty when not known
  std::vector<CalibrationCapture> captures;
  // The GUM budget of the nine parameters (type A and the reference quantities' type B,
  // expanded): absent when nobody asked for one (a file written before it existed).
  std::optional<UncertaintyBudget> budget;
  // What limits it beyond the captures' noise; empty when nothing does (issue 29).
  std::vector<UncertaintyLimit> limited_by;

  // The adopted effect called `name`; nullptr when there is none.
  const CalibrationEffect* FindEffect(std::string_view name) const;
  // The held mark of parameter `index` (ParameterIndex); nullptr when it was fitted.
  const HeldMark* FindHeld(int index) const;
  std::vector<std::string> EffectNames() const;
};

// The fit statistics of `summary`.
FitStatistics MakeFitStatistics(const FitSummary& summary);

// Every capture of `all` as listed in a calibration: used ones with their residual from
// `summary` (when it is usable), left-out ones with their reason.
std::vector<CalibrationCapture> MakeCalibrationCaptures(const std::vector<Capture>& all,
                                                        const FitSummary& summary);

// The calibration of the base model alone (`summary` must be usable).
Calibration MakeCalibration(const FitSummary& summary, const GravitySpec& gravity,
                            const std::vector<Capture>& all, const std::string& source);

// The calibration a diagnosis ends with: its final model (with the adopted effects, their
// parameters from the final fit) when `adopt_effects`, else its base model; the stages' per-
// capture residuals; the diagnosis outcome. The chosen fit must be usable.
Calibration MakeCalibration(const DiagnosisReport& diagnosis, bool adopt_effects,
                            const GravitySpec& gravity, const std::vector<Capture>& all,
                            const std::string& source);

}  // namespace accelcal

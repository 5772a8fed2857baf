// The calibration report's content, gathered once so that the three renderers (report_text.h,
// report_html.h, report_json.h) show the same numbers and never derive any themselves.
//
// Built from a typed calibration (calibration/calibration.h: the parameters, the fit statistics,
// the adopted effects and each capture's residual under each stage of the model, as the fit and
// the diagnosis computed them: nothing is refitted here) plus, when the report comes from a
// session, what the session recorded: its metadata (device, operator, dates), the captures with
// their raw samples (per-capture noise and temperature range), the procedure's pass/fail
// limits, and optional noise and Allan-deviation analyses (read by io/allan_file.h and
// io/noise_file.h). Whatever is absent is reported as "not recorded"; nothing is guessed.
//
// Units: SI (m/s^2, s, degC) except where a name says counts; the noise and Allan sections keep
// the unit their JSON states ("counts" or "m/s^2").
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/report/bench_time.h"
#include "accelcal/base/capture.h"
#include "accelcal/calibration/calibration.h"
#include "accelcal/report/certificate.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_gaps.h"
#include "accelcal/session/session_journal.h"

namespace accelcal {

// Who, what, when, where. Empty strings mean "not recorded".
struct ReportMeta {
  std::string device;         // serial, as typed
  std::string operator_name;  // as typed
  std::string date_utc;       // when the calibration was made (ISO 8601)
  std::string place;          // as typed (input key "place"); the gravity's location is separate
  std::string session_name;
  std::string session_path;
  std::string procedure;      // the procedure's title
  std::string source;         // the sample source ("sim", "serial:/dev/ttyUSB0")
  // The lab's certificate number (assigned when the session was published to the lab's store,
  // docs/lab.md); empty: the certificate carries the session's own (certificate.h).
  std::string certificate_number;
  // A session fitted again with corrected inputs (`accelcal refit`): each refit with what it
  // changed, and that the earlier calibrations are kept; empty for a session fitted once.
  std::vector<std::string> history;
};

// One axis of an Allan-deviation analysis (the shape of allan.json, docs/certificate.md, "Reports").
struct AllanAxis {
  double noise_density = kNaN;     // unit/sqrt(Hz)
  double bias_instability = kNaN;  // unit
  double random_walk = kNaN;       // unit*sqrt(Hz) = unit/sqrt(s) (rate random walk K); NaN when absent
  double max_drift = kNaN;         // unit
  std::vector<double> tau_s, adev, adev_lo, adev_hi;  // same length; lo/hi may be empty
};

struct AllanSection {
  std::string unit;                // "counts" or "m/s^2"
  double rate_hz = kNaN;
  std::array<std::optional<AllanAxis>, 3> axes;  // x, y, z; absent axes stay empty
  std::string source;              // file or "session result"
};

struct NoiseAxis {
  double std = kNaN;                 // unit
  double noise_density = kNaN;       // unit/sqrt(Hz)
  double bias_repeatability = kNaN;  // unit
};

struct NoiseSection {
  std::string unit;
  std::array<std::optional<NoiseAxis>, 3> axes;
  std::string source;
};

struct ReportCapture {
  CalibrationCapture record;
  double noise_counts = kNaN;  // RMS over the axes of the samples' std; NaN without samples
  double temp_min_c = kNaN;
  double temp_max_c = kNaN;
  // |a^p| of the final model = reference + residual, m/s^2; NaN when not used.
  double magnitude_mps2() const { return record.reference_mps2 + record.residual_mps2; }
};

struct ReportParameter {
  std::string name, unit;
  double value = kNaN;
  double sigma = kNaN;  // the fit's 1-sigma (type A); NaN when held
  bool held = false;    // held at `value`, not fitted (a reduced model: Calibration::held says why)
  // U as the certificate states it (limit_checks.h): the budget's, else 2 sigma; NaN when held.
  double expanded = kNaN;
};

// The residuals of every capture under one model: the base model, then after each adopted effect.
struct ResidualStage {
  std::string name;                    // "base model", "+ temperature_bias", ...
  std::vector<double> residual_mps2;   // one per ReportModel::captures entry; NaN when not used
  double rms_mps2 = kNaN;
};

struct ReportEffect {
  std::string name;
  double rms_before_mps2 = kNaN;
  double rms_after_mps2 = kNaN;
  double chi2_per_dof_before = kNaN;
  double chi2_per_dof_after = kNaN;
  bool corrects_readings = false;
  std::string evidence;
  std::vector<ReportParameter> parameters;
};

struct LimitCheck {
  std::string what;      // "residual RMS", "U (k = 2) of the scales", "scales from nominal"
  std::string unit;      // "m/s^2"
  double value = kNaN;   // measured: the value, the U, or the largest deviation from nominal
  double limit = kNaN;   // the limit; for a guard band, the acceptance limit (tolerance - U)
  bool at_least = false; // true: value >= limit passes; false: value <= limit passes
  bool pass = false;
  // The parameter judged (the worst of its group: "scale_y"); empty for the fit's checks.
  std::string parameter;
  // How it was judged, when not plainly: "tolerance 7.5 % narrowed by U = 0.05 % (guard band)".
  std::string rule;
  // Not met: why, and what would bring it within (the dominant parts of U and the uncertainty
  // each would need: limit_checks.h); empty when met.
  std::string why;
  bool on_uncertainty = false;  // a limit on U (the calibration cannot show conformity)
};

// PASS: every limit met and nothing required missing. FAIL: a limit not met (a limit on U not
// met: the calibration cannot show conformity). INCOMPLETE: the limits met (or none stated),
// but something the verdict stands on is missing (completeness.h): a capture damaged in the
// session file, a required step or its capture (left out by the fit too), a required
// identification, the equipment's identification, the uncertainty of a reference quantity the
// limits on U need, or which of gravity and turntable is right (a speed or radius scale found:
// the data cannot tell the two apart). NO LIMITS STATED: complete, but nothing to judge.
enum class Verdict { kPass, kFail, kNoLimits, kIncomplete };
std::string_view VerdictToString(Verdict v);  // "PASS", "FAIL", "NO LIMITS STATED", "INCOMPLETE"

// The effects whose size a gravity error would take for its own (only w^2 r / g is seen; the
// effect says so: Effect::TakesGravityErrorForItsOwn). False for an unknown name.
bool TakesGravityErrorForItsOwn(const std::string& effect_name);
// Empty, or (when `effect_names` hold a speed or radius effect, whatever the gravity's source)
// what the operator must know: a gravity error gives the same signature, the gravity that was
// used, and both checks to make.
std::string GravityAmbiguityNote(const GravitySpec& gravity, const std::vector<std::string>& effect_names);

struct ReportModel {
  ReportMeta meta;
  std::string gravity_text;          // GravitySpec::Describe()
  double gravity_mps2 = kNaN;
  std::string fit_source;            // the calibration's "source"
  std::string tool;                  // "accelcal X.Y.Z" that made the report
  std::vector<ReportParameter> parameters;  // the nine, in ParameterIndex order
  // What the nine parameters mean physically and what a magnitude fit cannot resolve (and, for
  // an adopted effect it sees only in part, what of it is seen), one paragraph each; every
  // renderer shows them beside the parameters.
  std::vector<std::string> parameter_notes;
  // Fit statistics (the calibration's "fit"); NaN / empty when the file lacks them.
  std::string termination, optimizer;
  int captures_used = 0;
  int dof = 0;
  double chi2_per_dof = kNaN;
  double condition_number = kNaN;
  std::vector<std::string> warnings;
  double residual_rms_mps2 = kNaN;
  double residual_max_abs_mps2 = kNaN;
  double noise_rms_mps2 = kNaN;      // RMS of the used captures' sigma: what noise explains
  // Some runs' sigma holds their own radius too (a fixture's board off the plate's reference:
  // its budget has the "run's own radius" line), so noise_rms_mps2 is what noise and those
  // radii explain; the reports say so.
  bool sigma_has_own_radius = false;
  std::vector<ReportCapture> captures;
  int captures_left_out = 0;
  std::vector<ResidualStage> stages; // base first; only the final one from a file alone
  std::vector<ReportEffect> effects; // adopted, in order
  std::string diagnosis_conclusion;  // the diagnosis in a paragraph; empty when it did not run
  // How far each pose taken again (a reference pose repeated between the turntable runs and at
  // the end) moved since its first capture, one sentence per pose (pose_repeat.h's path); empty
  // when no pose was taken twice.
  std::vector<std::string> pose_repeat_paths;
  double temp_min_c = kNaN;          // over all samples of all captures; NaN: not recorded
  double temp_max_c = kNaN;
  std::optional<NoiseSection> noise;
  std::optional<AllanSection> allan;
  std::vector<LimitCheck> checks;
  std::optional<SessionGaps> gaps;   // a session's; absent for a calibration file alone
  // Why the verdict is INCOMPLETE (required steps and identification missing, the gravity
  // ambiguity), in words; empty when nothing is missing.
  std::vector<std::string> incomplete;
  Verdict verdict = Verdict::kNoLimits;
  std::optional<UncertaintyBudget> budget;  // the calibration's
  Certificate certificate;
  // A wizard session's bench time, planned and spent, with each parameter's planned and reached
  // U (bench_time.h); absent for a calibration file alone or a session from before the plan.
  std::optional<ReportBenchTime> bench_time;
};

// What the report takes from one of the session's captures: the statistics of its samples
// (their noise, their temperature range), not the samples (at 10 kHz a session's captures are
// tens of MB, already held by whoever builds the report).
struct ReportCaptureStats {
  int id = 0;
  CaptureStats stats;
};
// The statistics of `capture` (its own, computed once), and of each of `captures`.
ReportCaptureStats ReportStatsOf(const Capture& capture);
std::vector<ReportCaptureStats> ReportStatsOf(const std::vector<Capture>& captures);

struct ReportInputs {
  Calibration calibration;
  ReportMeta meta;
  // The session's captures; empty when the report comes from a file alone.
  std::vector<ReportCaptureStats> captures;
  std::optional<ProcedureLimits> limits;
  std::optional<AllanSection> allan;
  std::optional<NoiseSection> noise;
  std::optional<SessionGaps> gaps;  // a wizard session's (its result carries them)
  // The session's captures found damaged in its file (DamagedCapture::Describe), left out of
  // `captures`: the report cannot show them, so its verdict is INCOMPLETE.
  std::vector<std::string> damaged_captures;
  // The bench's equipment (the procedure's, as edited at the welcome): the certificate's list
  // and traceability; empty when not known.
  std::vector<EquipmentItem> equipment;
  // The procedure's nominal zero-g level, counts: the certificate states the offset from it in
  // m/s^2 and mg (from 0 counts when absent); the tolerance on the biases is around it.
  std::optional<Eigen::Vector3d> nominal_bias_counts;
  // A wizard session's welcome answer to the equipment question, as typed (empty: none); the
  // caller that knows the procedure applies it to `equipment` (app/wizard/equipment_input.h).
  std::string equipment_answer;
  // The session's bench time (BenchTimeFromInputs); its reached U is filled from the budget.
  std::optional<ReportBenchTime> bench_time;
  // The procedure's nominal scale, counts/(m/s^2): the tolerance on the scales is around it.
  std::optional<Eigen::Vector3d> nominal_scale_counts_per_mps2;
};

// Gathers everything; derives nothing the calibration already states.
ReportModel BuildReportModel(const ReportInputs& inputs);

// Device, operator and place from a journal's inputs (keys "device", "operator", "place" at
// any step; the latest step id wins when two steps hold one).
void FillMetaFromInputs(const std::map<std::string, std::map<std::string, std::string>>& inputs,
                        ReportMeta* meta);

// The notes of ReportModel::parameter_notes for a calibration with these adopted effects: the
// nine parameters', then each effect's own (Effect::ReportNote) after its name.
std::vector<std::string> ParameterNotes(const std::vector<std::string>& effect_names);

// Text for an absent value in every renderer.
inline constexpr const char* kNotRecorded = "not recorded";

}  // namespace accelcal

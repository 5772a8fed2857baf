// A calibration procedure as data: the steps a wizard session walks through, read from TOML at
// run time (procedures/*.toml, by io/procedure_file.h; the format is in docs/guide.md, "Procedures").
//
// Units: deg for tolerances shown to the operator, s for durations, m and rpm for the turntable,
// g for the accelerometer's range, counts and counts per m/s^2 for the nominal model.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/base/capture_set.h"
#include "accelcal/base/sensor_model.h"
#include "accelcal/session/equipment.h"
#include "accelcal/session/procedure_target.h"
#include "accelcal/session/step_kind.h"

namespace accelcal {

struct ProcedureStep {
  std::string id;     // unique in the procedure; the journal's step id
  StepKind kind = StepKind::kStatic;
  std::string title;  // shown to the operator
  // kStatic / kRecord / kLevel: "up" in the platform frame (normalized), and its name.
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  std::string pose_name;
  // kTurntable: the defaults offered to the operator, and the mounting.
  double radius_m = kNaN;
  double rpm = kNaN;
  SensorAxis radial_axis = SensorAxis::kPlusX;
  SensorAxis up_axis = SensorAxis::kPlusZ;
  double duration_s = 10.0;  // capture length, s
  double timeout_s = 60.0;   // give up after this long without an accepted capture, s
  double tolerance_deg = 1.5;  // kLevel: largest accepted tilt per axis, deg
  // kRecord: the record is committed in chunks of this much of its time, s (an interruption
  // loses at most one chunk).
  double chunk_s = kDefaultRecordChunkS;
  // kAnalysis: the record step analysed (an earlier step of kind record), and how: "allan"
  // (Allan deviation, IEEE 952 read-offs, drift: analysis/record_analysis.h) or "noise"
  // (standard deviation, Welch noise density, normality: analysis/noise_analysis.h).
  std::string record_step;
  std::string method;
  // The calibration needs this step: skipping it (or having its capture left out) makes the
  // report's verdict INCOMPLETE. TOML `required`, default true.
  bool required = true;
  // A kind's own fields that none of the members above holds (step_kind.h); null for the
  // kinds of the table.
  std::shared_ptr<const StepOwnFields> own_fields;

  static constexpr double kDefaultRecordChunkS = 10.0;
};

// How a value is judged against its tolerance (ILAC-G8:09/2019, "Guidelines on Decision Rules
// and Statements of Conformity"): the procedure chooses ([limits] decision_rule).
enum class DecisionRule {
  kSimpleAcceptance,  // 4.2.1: the value as found within the tolerance passes
  kGuardBand,         // 4.2.2: within the tolerance narrowed by w = U (the acceptance limit)
};
// "simple" / "guard_band" (the file's words), and in words for the certificate.
std::string_view DecisionRuleKey(DecisionRule rule);
std::optional<DecisionRule> DecisionRuleFromKey(std::string_view key);

// Pass/fail limits of the calibration, checked by the report ([limits] in the procedure file).
// NaN (or 0 for min_captures): no limit stated. Units in the names.
//
// The uncertainty limits are on U, the expanded uncertainty (k = 2, about 95 %) of the
// certificate's budget (type A and type B): the verdict is decided on the uncertainty the
// certificate prints. Files of the first format stated them on the fit's 1-sigma
// (max_bias_sigma_counts, max_scale_sigma_ppm, max_misalignment_sigma_rad); such a key is read as
// the limit on U = 2 x its value (`converted` says so), and is then compared with the whole
// budget's U, not the fit's 1-sigma alone.
struct ProcedureLimits {
  double max_residual_rms_mps2 = kNaN;      // RMS of the final fit's residuals
  double max_residual_rms_noise = kNaN;     // same, over the RMS of the captures' own sigma
  double max_bias_U_counts = kNaN;          // largest U (k = 2) of bias_x/y/z, counts
  double max_scale_U_ppm = kNaN;            // largest U (k = 2) of scale_i over scale_i, ppm
  double max_misalignment_U_rad = kNaN;     // largest U (k = 2) of a_yz, a_zy, a_zx, rad
  // Tolerances on the values (a datasheet's range), judged by `decision_rule`:
  double bias_tolerance_counts = kNaN;      // |bias_i - nominal zero-g level| at most, counts
  double scale_tolerance_percent = kNaN;    // |scale_i / nominal scale - 1| at most, %
  double misalignment_tolerance_rad = kNaN; // |a_yz|, |a_zy|, |a_zx| at most, rad
  int min_captures = 0;                     // captures used by the fit
  DecisionRule decision_rule = DecisionRule::kSimpleAcceptance;
  // A first-format key read by the stated rule, in words ("max_scale_sigma_ppm = 2000 (1-sigma)
  // read as max_scale_U_ppm = 4000 (U, k = 2)"); empty when none.
  std::vector<std::string> converted;

  bool Any() const;  // at least one limit stated
  bool AnyOnUncertainty() const;  // a limit on U is stated
  bool AnyTolerance() const;      // a tolerance on the values is stated
};

// What the session must know before it calibrates ([requirements] in the procedure file).
struct ProcedureRequirements {
  bool device_serial = false;  // the welcome refuses an empty device serial
  bool operator_name = false;  // ... an empty operator
  // The standard gravity is refused at the welcome: a measured value or a location is needed
  // (a turntable calibration's scales are only as good as the local gravity).
  bool local_gravity = false;
};

struct Procedure {
  std::string title;
  // The titles this procedure had before (former_titles): a session records its procedure's
  // title, and one recorded under a former title ran this procedure.
  std::vector<std::string> former_titles;
  std::string source_name;  // the file it came from

  // `recorded` (a session's procedure) names this procedure, by its title or a former one.
  bool IsTitled(std::string_view recorded) const {
    if (recorded == title) return true;
    for (const std::string& former : former_titles)
      if (recorded == former) return true;
    return false;
  }
  double range_g = 6.0;     // the accelerometer's full-scale range, +- g
  SensorModel nominal;      // datasheet scale and bias (no misalignment): the rough model
  AdcRange adc_range{0.0, 4095.0};  // the ADC's output range, counts
  double orientation_tolerance_deg = 15.0;
  double std_multiplier = 1.5;        // static stability: std limit in noise-floor sigmas
  double trend_multiplier = 2.0;      // static stability: trend limit in noise-floor sigmas
  double turntable_tolerance = 0.10;  // relative centripetal mismatch accepted
  // Largest spin-axis tilt of the turntable accepted, deg: beyond it the capture is refused with
  // leveling advice (within it the once-per-revolution swing is removed from the samples).
  double turntable_tilt_tolerance_deg = 0.5;
  // The sensor's noise on a still bench, counts per axis (std): the noise floor is checked
  // against it. NaN: not stated (the floor is then checked only against the static captures).
  Eigen::Vector3d expected_noise_counts = Eigen::Vector3d::Constant(kNaN);
  // A noise floor above this many times the expected noise on any axis is refused (the sensor
  // was not still while it was measured); > 1.
  double noise_floor_max_ratio = 2.0;
  ProcedureRequirements requirements;  // [requirements]; nothing required when absent
  ProcedureLimits limits;             // [limits]; all absent when the table is
  ProcedureTarget target;             // [target]; no uncertainty stated when the table is absent
  // [equipment]: the bench's items with their identification, uncertainty and traceability
  // (the uncertainty budget's type B inputs); empty when the table is absent.
  std::vector<EquipmentItem> equipment;
  std::vector<ProcedureStep> steps;

  // The poses of the static steps other than the six faces (to name a wrong pose).
  std::vector<Eigen::Vector3d> TiltedPoses() const;
};

}  // namespace accelcal

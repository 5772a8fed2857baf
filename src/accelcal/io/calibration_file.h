// The calibration file: JSON, format "accelcal-calibration/1" (schema in README.md).
//
// Written with full round-trip precision; read strictly: a missing field, a wrong type, a
// non-finite number or an unknown format is an InputError naming the field, so a damaged file
// is never applied as if it were good.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "accelcal/base/capture.h"
#include "accelcal/calibration/fit/fit_summary.h"
#include "accelcal/base/gravity.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

inline constexpr const char* kCalibrationFormat = "accelcal-calibration/1";

// One capture as listed in the file: what was used, why something was left out, its residual.
struct CaptureRecord {
  int id = 0;
  CaptureKind kind = CaptureKind::kStatic;
  std::string label;
  bool used = true;
  std::string reason;                 // why it was left out; empty when used
  long n_samples = 0;
  double residual_mps2 = kNaN;        // NaN when not used
  double reference_mps2 = kNaN;
  double sigma_mps2 = kNaN;
  double radius_m = kNaN;
  double rpm = kNaN;
  double t_start_s = kNaN;
  double t_end_s = kNaN;
  Eigen::Vector3d mean_counts = Eigen::Vector3d::Constant(kNaN);
};

struct Calibration {
  SensorModel model;
  SensorModel uncertainty;            // 1-sigma of each parameter, same fields
  GravitySpec gravity;
  double residual_rms_mps2 = kNaN;
  double residual_max_abs_mps2 = kNaN;
  std::string source;                 // what was fitted (file name)
  nlohmann::json fit = nlohmann::json::object();     // fit statistics (see README)
  nlohmann::json effects = nlohmann::json::array();  // adopted effects, in order (diagnosis)
  std::vector<CaptureRecord> captures;
};

// Every capture of `all` as a record: used ones with their residual from `summary` (when it is
// usable), left-out ones with their reason.
std::vector<CaptureRecord> MakeCaptureRecords(const std::vector<Capture>& all,
                                              const FitSummary& summary);

// The calibration that `summary` describes (must be usable), with every capture of `all`
// listed: used ones with their residuals, left-out ones with their reason.
Calibration MakeCalibration(const FitSummary& summary, const GravitySpec& gravity,
                            const std::vector<Capture>& all, const std::string& source);

nlohmann::json CalibrationToJson(const Calibration& cal);
Calibration CalibrationFromJson(const nlohmann::json& j, const std::string& source_name);

void WriteCalibrationFile(const std::string& path, const Calibration& cal);
Calibration ReadCalibrationFile(const std::string& path);

}  // namespace accelcal

#include "accelcal/io/export/diagonal_correction.h"

#include <cmath>

#include <Eigen/LU>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accelcal/base/error.h"
#include "accelcal/base/linear_algebra.h"

namespace accelcal {

std::string DriverScaleOptions::Validate() const {
  for (int j = 0; j < 3; ++j) {
    if (!std::isfinite(nominal_scale_counts_per_mps2(j)) || nominal_scale_counts_per_mps2(j) <= 0.0)
      return "the sensor's nominal scale (counts per m/s^2, the datasheet's sensitivity) is needed: "
             "the flight stack's driver divides by it before the calibration is applied";
    if (!std::isfinite(nominal_bias_counts(j)))
      return "the nominal zero-g level (counts) is not a finite number";
  }
  return {};
}

double MisalignmentLossMaxMps2(const SensorModel& model, double magnitude_mps2) {
  const Eigen::Matrix3d error = model.Misalignment().inverse() - Eigen::Matrix3d::Identity();
  return magnitude_mps2 * SingularValues(error)(0);
}

DiagonalCorrection ToDiagonalCorrection(const Calibration& cal, const DriverScaleOptions& options) {
  if (const std::string why = options.Validate(); !why.empty()) throw Error(why);
  const SensorModel& m = cal.model;
  const SensorModel& s = cal.uncertainty;
  const Eigen::Vector3d& S = options.nominal_scale_counts_per_mps2;
  DiagonalCorrection c;
  c.offset_mps2 = (m.bias_counts - options.nominal_bias_counts).cwiseQuotient(S);
  c.scale = S.cwiseQuotient(m.scale_counts_per_mps2);
  c.offset_sigma_mps2 = s.bias_counts.cwiseQuotient(S);
  // d(S/k) = S/k^2 dk
  c.scale_sigma = c.scale.cwiseProduct(s.scale_counts_per_mps2.cwiseQuotient(m.scale_counts_per_mps2));
  c.misalignment_loss_max_mps2 = MisalignmentLossMaxMps2(m, cal.gravity.gravity_mps2);
  return c;
}

void AddDiagonalLimits(const Calibration& cal, const DiagonalCorrection& correction,
                       const std::string& stack, ExportResult* result) {
  const SensorModel& m = cal.model;
  result->cannot_hold.push_back(fmt::format(
      "misalignment (a_yz {:.3g}, a_zy {:.3g}, a_zx {:.3g} rad): {} holds only a per-axis offset and "
      "scale, no off-diagonal terms; dropping it costs up to {:.3g} m/s^2 ({:.3g} % of g) on a "
      "specific force of magnitude g",
      m.a_yz_rad, m.a_zy_rad, m.a_zx_rad, stack, correction.misalignment_loss_max_mps2,
      100.0 * correction.misalignment_loss_max_mps2 / cal.gravity.gravity_mps2));
  const std::vector<std::string> effects = SensorEffectNames(cal);
  if (!effects.empty())
    result->cannot_hold.push_back(fmt::format(
        "the sensor effects {} (not representable as one offset and scale per axis)",
        fmt::join(effects, ", ")));
  for (std::string& note : SessionEffectNotes(cal)) result->notes.push_back(std::move(note));
}

}  // namespace accelcal

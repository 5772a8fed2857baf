#include "accelcal/base/sensor_model.h"

#include <cmath>
#include <string>

namespace accelcal {

std::string_view ParameterName(int index) {
  static constexpr std::array<std::string_view, kNumBaseParameters> kNames = {
      "bias_x", "bias_y", "bias_z", "scale_x", "scale_y", "scale_z", "a_yz", "a_zy", "a_zx"};
  return (index >= 0 && index < kNumBaseParameters) ? kNames[index] : "?";
}

std::string_view ParameterUnit(int index) {
  if (index >= kBiasX && index <= kBiasZ) return "counts";
  if (index >= kScaleX && index <= kScaleZ) return "counts/(m/s^2)";
  if (index >= kMisYZ && index <= kMisZX) return "rad";
  return "?";
}

Eigen::Matrix3d SensorModel::Misalignment() const {
  Eigen::Matrix3d t;
  t << 1.0, -a_yz_rad, a_zy_rad,
       0.0, 1.0, -a_zx_rad,
       0.0, 0.0, 1.0;
  return t;
}

Eigen::Vector3d SensorModel::Calibrate(const Eigen::Vector3d& raw_counts) const {
  const Eigen::Vector3d along_axes_mps2 =
      (raw_counts - bias_counts).cwiseQuotient(scale_counts_per_mps2);
  return Misalignment() * along_axes_mps2;
}

Eigen::Vector3d SensorModel::Raw(const Eigen::Vector3d& platform_mps2) const {
  // T is unit upper triangular, so the triangular solve is exact and cheap.
  const Eigen::Vector3d along_axes_mps2 =
      Misalignment().triangularView<Eigen::UnitUpper>().solve(platform_mps2);
  return scale_counts_per_mps2.cwiseProduct(along_axes_mps2) + bias_counts;
}

Eigen::Matrix<double, kNumBaseParameters, 1> SensorModel::ToVector() const {
  Eigen::Matrix<double, kNumBaseParameters, 1> p;
  p << bias_counts, scale_counts_per_mps2, a_yz_rad, a_zy_rad, a_zx_rad;
  return p;
}

SensorModel SensorModel::FromVector(const Eigen::Ref<const Eigen::VectorXd>& p) {
  SensorModel m;
  m.bias_counts = p.segment<3>(kBiasX);
  m.scale_counts_per_mps2 = p.segment<3>(kScaleX);
  m.a_yz_rad = p(kMisYZ);
  m.a_zy_rad = p(kMisZY);
  m.a_zx_rad = p(kMisZX);
  return m;
}

std::string SensorModel::Validate() const {
  const auto v = ToVector();
  for (int i = 0; i < kNumBaseParameters; ++i) {
    if (!std::isfinite(v(i))) return std::string(ParameterName(i)) + " is not a finite number";
  }
  for (int i = kScaleX; i <= kScaleZ; ++i) {
    if (v(i) <= 0.0) return std::string(ParameterName(i)) + " must be positive (counts per m/s^2)";
  }
  // Every reading a 32-bit ADC can give must calibrate to a finite number (scale 1e-320 would
  // give inf, then nan through T): the map is linear, so its extremes are at the corners.
  constexpr double kLargestRawCounts = 2147483648.0;  // 2^31
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d raw(corner & 1 ? kLargestRawCounts : -kLargestRawCounts,
                              corner & 2 ? kLargestRawCounts : -kLargestRawCounts,
                              corner & 4 ? kLargestRawCounts : -kLargestRawCounts);
    if (!Calibrate(raw).allFinite())
      return "a reading of 2^31 counts would calibrate to an infinite value: a scale is too small "
             "or a misalignment too large for any sensor";
  }
  return {};
}

}  // namespace accelcal

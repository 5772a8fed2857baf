// The accelerometer model of the lab chapter (shared/seed), stated once for the whole project.
//
//   raw = K a^a + b          a^p = T a^a          =>   a^p = T K^-1 (raw - b)
//
//   raw   raw reading of the three axes, in ADC counts, axis order (x, y, z).
//   a^a   specific force along the accelerometer's own (non-orthogonal) sensitivity axes, m/s^2.
//   a^p   specific force in the platform frame, m/s^2: x^p along x^a, y^p in the plane of x^a
//         and y^a, z^p completing a right-handed orthonormal frame (Titterton & Weston).
//   K     diag(kx, ky, kz), scale in counts per m/s^2 (positive).
//   b     bias (zero-g level), counts.
//   T     [[1, -a_yz, a_zy], [0, 1, -a_zx], [0, 0, 1]]; a_ij (rad) is the rotation of the i-th
//         sensitivity axis about the j-th platform axis. Signs are the seed's, exactly.
//
// Specific force is acceleration minus gravity: at rest on a level table it points up, |f| = g.
// All quantities are SI inside the program (m/s^2, rad, s, degC); counts only at the edge.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include <Eigen/Core>

namespace accelcal {

// Parameter vector layout used by the fit and its covariance: index -> meaning.
enum ParameterIndex : int {
  kBiasX = 0, kBiasY, kBiasZ,      // counts
  kScaleX, kScaleY, kScaleZ,       // counts per m/s^2
  kMisYZ, kMisZY, kMisZX,          // rad
  kNumBaseParameters               // = 9
};

// Name of parameter `index` as written in reports ("bias_x", "scale_y", "a_yz", ...).
std::string_view ParameterName(int index);
// Unit of parameter `index` ("counts", "counts/(m/s^2)", "rad").
std::string_view ParameterUnit(int index);

struct SensorModel {
  Eigen::Vector3d bias_counts = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale_counts_per_mps2 = Eigen::Vector3d::Ones();
  double a_yz_rad = 0.0;
  double a_zy_rad = 0.0;
  double a_zx_rad = 0.0;

  // T of the header comment.
  Eigen::Matrix3d Misalignment() const;
  // a^p = T K^-1 (raw - b), m/s^2.
  Eigen::Vector3d Calibrate(const Eigen::Vector3d& raw_counts) const;
  // raw = K T^-1 a^p + b, counts (no noise, no quantization): the forward model.
  Eigen::Vector3d Raw(const Eigen::Vector3d& platform_mps2) const;

  // The 9-vector in ParameterIndex order, and back.
  Eigen::Matrix<double, kNumBaseParameters, 1> ToVector() const;
  static SensorModel FromVector(const Eigen::Ref<const Eigen::VectorXd>& p);

  // Empty when usable; otherwise why not (non-finite value, scale not positive, or a reading
  // within +-2^31 counts that would calibrate to an infinite or undefined value).
  std::string Validate() const;
};

}  // namespace accelcal

// The calibration as a flight stack's per-axis correction of already-scaled readings, as
// ArduPilot (INS_ACCOFFS_*, INS_ACCSCAL_*) and PX4 (CAL_ACC0_*OFF, CAL_ACC0_*SCALE) hold it:
//
//   a_corrected_j = (a_driver_j - offset_j) * scale_j        m/s^2, per sensor axis j
//
// Both stacks' drivers turn counts into m/s^2 with the sensor's nominal (datasheet) scale
// before any calibration: a_driver = (raw - B) / S, S the nominal scale in counts per m/s^2, B
// the zero-g level the driver subtracts (0 for a digital sensor that reports signed counts; the
// ADC mid-scale for an analog one read through an ADC). With our model's diagonal part,
// a^a = K^-1 (raw - b) = (S / k) (a_driver - (b - B) / S), so exactly
//
//   offset_j = (b_j - B_j) / S_j   m/s^2        scale_j = S_j / k_j   (~1)
//
// What this form cannot hold: the misalignment T (no off-diagonal terms), so the stacks give
// a^a (along the sensor's non-orthogonal axes) where the calibration gives a^p = T a^a. The
// error for a specific force f of magnitude g: a^a - a^p = (T^-1 - I) f, largest over the
// sphere |f| = g at g times the largest singular value of T^-1 - I (computed exactly here).
// Sources: ArduPilot AP_InertialSensor_Backend::_rotate_and_correct_accel ("accel -= offset;
// accel.x *= scale.x ..."), PX4 src/lib/sensor_calibration/Accelerometer.hpp Correct()
// ("(data - thermal_offset - offset).emult(scale)"); both then rotate to the body frame.
#pragma once

#include <string>

#include <Eigen/Core>

#include "accelcal/io/export/export_result.h"

namespace accelcal {

// How the flight stack's driver scales raw counts (the datasheet's figures).
struct DriverScaleOptions {
  // Counts per m/s^2 that the driver divides by (nominal sensitivity), per axis. Required.
  Eigen::Vector3d nominal_scale_counts_per_mps2 = Eigen::Vector3d::Constant(kNaN);
  // Counts the driver subtracts before scaling (its zero-g level), per axis.
  Eigen::Vector3d nominal_bias_counts = Eigen::Vector3d::Zero();

  // Empty when valid: scales finite and positive, biases finite.
  std::string Validate() const;
};

struct DiagonalCorrection {
  Eigen::Vector3d offset_mps2;  // subtracted from the driver's m/s^2
  Eigen::Vector3d scale;        // then multiplied, dimensionless
  Eigen::Vector3d offset_sigma_mps2;  // 1-sigma, from the calibration's uncertainties
  Eigen::Vector3d scale_sigma;
  // Largest |a_diagonal - a^p| over specific forces of magnitude g_mps2 (the fit's gravity),
  // m/s^2: what dropping the misalignment costs.
  double misalignment_loss_max_mps2 = 0.0;
};

// Throws accelcal::Error when `options` is invalid.
DiagonalCorrection ToDiagonalCorrection(const Calibration& cal, const DriverScaleOptions& options);

// Largest |(T^-1 - I) f| over |f| = magnitude_mps2, m/s^2 (see above).
double MisalignmentLossMaxMps2(const SensorModel& model, double magnitude_mps2);

// The statements shared by ArduPilot's and PX4's exports: misalignment and sensor effects
// cannot be held (with the loss in m/s^2); `stack` names the target ("ArduPilot").
void AddDiagonalLimits(const Calibration& cal, const DiagonalCorrection& correction,
                       const std::string& stack, ExportResult* result);

}  // namespace accelcal

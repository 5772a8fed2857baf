// What an autopilot did to its accelerometer readings before it sent them, taken back.
// ArduPilot (AP_InertialSensor_Backend::_rotate_and_correct_accel) and PX4
// (sensor_calibration/Accelerometer.hpp, Correct()) both send
//
//   a_sent = R_board ((a_sensor - offset) .* scale)        m/s^2, per axis, then rotated
//
// with their stored calibration (INS_ACCOFFS/INS_ACCSCAL, CAL_ACCn_?OFF/?SCALE) and the board's
// orientation (AHRS_ORIENTATION, SENS_BOARD_ROT). Undone:
//
//   a_sensor = (R_board^T a_sent) ./ scale + offset
//
// which is the reading the autopilot's own driver produced, in the frame its calibration
// parameters apply in: a calibration of these readings is what goes back into those parameters
// (app/device/vehicle_writeback.h).
#pragma once

#include <string>

#include <Eigen/Core>

namespace accelcal::mavlink {

struct AccelUndo {
  Eigen::Matrix3d body_from_sensor = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  // What was undone, in words: "INS_ACCOFFS (0.1, -0.05, 0.2) m/s^2, INS_ACCSCAL (1.002, ...),
  // AHRS_ORIENTATION 0 (none)".
  std::string description;

  Eigen::Vector3d SensorFromSent(const Eigen::Vector3d& sent_mps2) const {
    return (body_from_sensor.transpose() * sent_mps2).cwiseQuotient(scale) + offset_mps2;
  }
};

}  // namespace accelcal::mavlink

// The board orientations autopilots store as one number (ArduPilot AHRS_ORIENTATION, PX4
// SENS_BOARD_ROT and CAL_ACCn_ROT), common.xml's MAV_SENSOR_ORIENTATION: 0 none, 1 yaw 45, ...,
// each a roll, then a pitch, then a yaw by multiples of 45 deg (and a few odd ones).
//
// The rotation takes a vector from the sensor's frame to the vehicle's body frame:
// v_body = Rz(yaw) Ry(pitch) Rx(roll) v_sensor, right-handed, angles as the name gives them.
// That is how ArduPilot's Vector3::rotate() acts (its rotations test checks every entry against
// Matrix3::from_euler(roll, pitch, yaw)); PX4 builds its rotation matrices from the same Euler
// angles (src/lib/conversion/rotation.cpp, get_rot_matrix).
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

namespace accelcal::mavlink {

struct SensorOrientation {
  int value = 0;
  std::string name;      // "ROLL_180_YAW_90"
  double roll_deg = 0.0, pitch_deg = 0.0, yaw_deg = 0.0;

  // body <- sensor.
  Eigen::Matrix3d BodyFromSensor() const;
};

// nullopt for a value this table does not hold (ArduPilot's 38, whose name does not follow the
// roll-pitch-yaw order, and 100, the custom rotation of AHRS_CUSTOM_*): such an orientation
// cannot be undone here.
std::optional<SensorOrientation> FindSensorOrientation(int value);

}  // namespace accelcal::mavlink

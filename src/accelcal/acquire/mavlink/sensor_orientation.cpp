#include "accelcal/acquire/mavlink/sensor_orientation.h"

#include <cmath>

#include <Eigen/Geometry>

namespace accelcal::mavlink {
namespace {

struct Entry {
  int value;
  const char* name;
  double roll, pitch, yaw;  // deg
};

// common.xml MAV_SENSOR_ORIENTATION (the same numbers as ArduPilot's enum Rotation,
// libraries/AP_Math/rotations.h, and PX4's src/lib/conversion/rotation.h).
constexpr Entry kTable[] = {
    {0, "NONE", 0, 0, 0},
    {1, "YAW_45", 0, 0, 45},
    {2, "YAW_90", 0, 0, 90},
    {3, "YAW_135", 0, 0, 135},
    {4, "YAW_180", 0, 0, 180},
    {5, "YAW_225", 0, 0, 225},
    {6, "YAW_270", 0, 0, 270},
    {7, "YAW_315", 0, 0, 315},
    {8, "ROLL_180", 180, 0, 0},
    {9, "ROLL_180_YAW_45", 180, 0, 45},
    {10, "ROLL_180_YAW_90", 180, 0, 90},
    {11, "ROLL_180_YAW_135", 180, 0, 135},
    {12, "PITCH_180", 0, 180, 0},
    {13, "ROLL_180_YAW_225", 180, 0, 225},
    {14, "ROLL_180_YAW_270", 180, 0, 270},
    {15, "ROLL_180_YAW_315", 180, 0, 315},
    {16, "ROLL_90", 90, 0, 0},
    {17, "ROLL_90_YAW_45", 90, 0, 45},
    {18, "ROLL_90_YAW_90", 90, 0, 90},
    {19, "ROLL_90_YAW_135", 90, 0, 135},
    {20, "ROLL_270", 270, 0, 0},
    {21, "ROLL_270_YAW_45", 270, 0, 45},
    {22, "ROLL_270_YAW_90", 270, 0, 90},
    {23, "ROLL_270_YAW_135", 270, 0, 135},
    {24, "PITCH_90", 0, 90, 0},
    {25, "PITCH_270", 0, 270, 0},
    {26, "PITCH_180_YAW_90", 0, 180, 90},
    {27, "PITCH_180_YAW_270", 0, 180, 270},
    {28, "ROLL_90_PITCH_90", 90, 90, 0},
    {29, "ROLL_180_PITCH_90", 180, 90, 0},
    {30, "ROLL_270_PITCH_90", 270, 90, 0},
    {31, "ROLL_90_PITCH_180", 90, 180, 0},
    {32, "ROLL_270_PITCH_180", 270, 180, 0},
    {33, "ROLL_90_PITCH_270", 90, 270, 0},
    {34, "ROLL_180_PITCH_270", 180, 270, 0},
    {35, "ROLL_270_PITCH_270", 270, 270, 0},
    {36, "ROLL_90_PITCH_180_YAW_90", 90, 180, 90},
    {37, "ROLL_90_YAW_270", 90, 0, 270},
    {39, "PITCH_315", 0, 315, 0},
    {40, "ROLL_90_PITCH_315", 90, 315, 0},
    {41, "PITCH_7", 0, 7, 0},
    {42, "ROLL_45", 45, 0, 0},
    {43, "ROLL_315", 315, 0, 0},
};

double Rad(double deg) { return deg * M_PI / 180.0; }

}  // namespace

Eigen::Matrix3d SensorOrientation::BodyFromSensor() const {
  return (Eigen::AngleAxisd(Rad(yaw_deg), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(Rad(pitch_deg), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(Rad(roll_deg), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

std::optional<SensorOrientation> FindSensorOrientation(int value) {
  for (const Entry& e : kTable)
    if (e.value == value) return SensorOrientation{e.value, e.name, e.roll, e.pitch, e.yaw};
  return std::nullopt;
}

}  // namespace accelcal::mavlink

// What a flight controller's own accelerometer calibration is, read over MAVLink, and how to
// take it back out of its readings (acquire/mavlink/accel_undo.h).
//
//   ArduPilot, IMU n = 0, 1, 2: INS_ACCOFFS_X/Y/Z, INS_ACC2OFFS_*, INS_ACC3OFFS_* (m/s^2),
//     INS_ACCSCAL_*, INS_ACC2SCAL_*, INS_ACC3SCAL_*, INS_ACC_ID/INS_ACC2_ID/INS_ACC3_ID, the
//     board's AHRS_ORIENTATION, and INS_TCALn_ENABLE (its temperature calibration, n = 1..3);
//   PX4, n = 0, 1, 2: CAL_ACCn_XOFF/YOFF/ZOFF (m/s^2), CAL_ACCn_XSCALE/..., CAL_ACCn_ID,
//     CAL_ACCn_ROT (-1: internal, the board's SENS_BOARD_ROT applies), SENS_BOARD_X_OFF/Y_OFF/
//     Z_OFF (deg), TC_A_ENABLE (its thermal compensation).
//
// A temperature calibration, a PX4 board offset angle or an orientation outside the table
// cannot be undone here: UndoOf says so, and the technician resets them on the vehicle instead
// (ResetWrites gives the PARAM_SETs of a neutral calibration).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/acquire/mavlink/accel_undo.h"
#include "accelcal/acquire/mavlink/param_client.h"

namespace accelcal {

enum class FlightStack { kArduPilot, kPx4, kUnknown };

// From a HEARTBEAT's autopilot field.
FlightStack StackOf(std::uint8_t autopilot);
// "ArduPilot", "PX4", "an unknown autopilot".
std::string StackName(FlightStack stack);

struct AccelParamNames {
  std::array<std::string, 3> offset;  // m/s^2
  std::array<std::string, 3> scale;
  std::string device_id;
  std::string sensor_rotation;        // PX4's CAL_ACCn_ROT; empty for ArduPilot
  std::string board_rotation;         // AHRS_ORIENTATION, SENS_BOARD_ROT
  std::array<std::string, 3> board_offset_deg;  // PX4's SENS_BOARD_?_OFF; empty for ArduPilot
  std::string thermal;                // INS_TCALn_ENABLE, TC_A_ENABLE

  std::vector<std::string> All() const;
};

// Throws accelcal::Error for an unknown stack or an IMU outside 0..2.
AccelParamNames AccelParamNamesFor(FlightStack stack, int imu);

struct VehicleAccelParams {
  FlightStack stack = FlightStack::kUnknown;
  int imu = 0;
  std::string vehicle;  // "system 1 component 1 (ArduPilot)"
  std::string link;     // "tcp:127.0.0.1:5760"
  AccelParamNames names;
  std::map<std::string, mavlink::ParamValue> values;
  std::vector<std::string> unanswered;

  // The parameter as a number (integers as the stack encodes them); nullopt when unanswered.
  std::optional<double> Number(const std::string& name) const;
};

// Reads the IMU's parameters from the vehicle on `link`. Throws accelcal::Error naming the link
// when no vehicle answers the link at all, or the vehicle is neither ArduPilot nor PX4.
VehicleAccelParams ReadVehicleAccelParams(mavlink::Connection& link, int imu,
                                          const mavlink::ParamExchange& exchange = {});

// What they are, one fact per line, for the technician: "INS_ACCOFFS: x 0.12, y -0.05, z 0.3
// m/s^2", "AHRS_ORIENTATION 0 (NONE)", "INS_TCAL1_ENABLE 0 (no temperature calibration)",
// and the unanswered ones.
std::vector<std::string> DescribeVehicleAccelParams(const VehicleAccelParams& params);

// The undo of this calibration; nullopt with *why when it cannot be undone here (a parameter
// unanswered, a temperature calibration on, a board offset angle, an orientation outside the
// table).
std::optional<mavlink::AccelUndo> UndoOf(const VehicleAccelParams& params, std::string* why);

// One parameter write: what goes into a PARAM_SET.
struct ParamWrite {
  std::string name;
  double value = 0.0;
  std::uint8_t type = 9;  // MAV_PARAM_TYPE_REAL32
};

// The writes that give the IMU a neutral calibration (offsets 0, scales 1; the temperature
// calibration off), for a technician who would rather reset the vehicle's calibration than have
// it undone.
std::vector<ParamWrite> ResetWrites(const VehicleAccelParams& params);

}  // namespace accelcal

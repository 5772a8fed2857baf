// Before samples of a MAVLink vehicle are used: each IMU's own calibration read, said, and taken
// back out of its readings (or, on request, left in). What `accelcal wizard` and `accelcal record` do
// before they start on a mavlink: source; the wizard's device step (to come) calls the same.
#pragma once

#include <string>
#include <vector>

#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/app/device/vehicle_calibration.h"

namespace accelcal {

enum class VehicleCalibrationChoice {
  kUndo,  // take the vehicle's correction back out of every sample (the sensor's own response)
  kAsIs,  // leave it in (said: the calibration then describes the sensor after it)
};

struct VehiclePreparation {
  // What each IMU's calibration is and what was done with it: one block per IMU instance of the
  // source, each opened by the line naming its vehicle, link and IMU.
  std::vector<std::string> lines;
  bool undone = false;  // every IMU's taken out
  // Non-empty when the undo was asked but cannot be done for an IMU: which, why, and what to do
  // instead (one sentence per IMU that cannot).
  std::string refused;
};

// Reads the vehicle's calibration of each IMU instance the source reads (one for mavlink:...,imu=N;
// the instances of a vehicle's IMUs at once, mavlink_sensor_set.h) through the source's own link
// (samples that arrive meanwhile are kept) and applies the choice to each instance's lane. Undo
// refused for one IMU: no IMU's undo is set (the session is not to start: that IMU would be
// calibrated relative to its old calibration). Throws accelcal::Error when no vehicle answers the
// link at all, or it is neither ArduPilot nor PX4.
VehiclePreparation PrepareVehicleSource(MavlinkSource& source, VehicleCalibrationChoice choice,
                                        const mavlink::ParamExchange& exchange = {});

}  // namespace accelcal

// Before samples of a MAVLink vehicle are used: its own calibration read, said, and taken back
// out of its readings (or, on request, left in). What `accelcal wizard` and `accelcal record` do
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
  std::vector<std::string> lines;  // what the vehicle's calibration is and what was done
  bool undone = false;
  // Non-empty when the undo was asked but cannot be done: why, and what to do instead.
  std::string refused;
};

// Reads the vehicle's calibration of the source's IMU through the source's own link (samples
// that arrive meanwhile are kept) and applies the choice to the source. Throws accelcal::Error
// when no vehicle answers the link at all.
VehiclePreparation PrepareVehicleSource(MavlinkSource& source, VehicleCalibrationChoice choice,
                                        const mavlink::ParamExchange& exchange = {});

}  // namespace accelcal

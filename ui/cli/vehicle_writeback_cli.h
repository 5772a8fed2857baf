// `accelcal export-cal CAL --to mavlink:LINK[,imu=N] [--apply]`: the calibration written into a
// flight controller's own parameters (app/device/vehicle_writeback.h). Without --apply it only
// says what it would send.
#pragma once

#include <optional>
#include <string>

#include "accelcal/calibration/calibration.h"
#include "accelcal/io/export/diagonal_correction.h"

namespace accelcal::cli {

// `driver`: the driver's scaling given on the command line; else the calibration's reading unit
// decides it. Prints to stdout; throws accelcal::Error when the write-back stopped or cannot start.
void WriteBackToVehicle(const Calibration& cal, const std::string& target,
                        const std::optional<DriverScaleOptions>& driver, bool apply);

}  // namespace accelcal::cli

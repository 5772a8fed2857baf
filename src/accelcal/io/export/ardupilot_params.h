// Export of a calibration as an ArduPilot parameter file: INS_ACCOFFS_{X,Y,Z} (m/s^2) and
// INS_ACCSCAL_{X,Y,Z} (dimensionless), the per-axis correction of diagonal_correction.h, which
// ArduPilot applies in the sensor frame before rotating to the body frame
// (AP_InertialSensor_Backend::_rotate_and_correct_accel: accel -= INS_ACCOFFS; accel *= INS_ACCSCAL).
//
// File format: one `NAME,VALUE` line per parameter and `#` comment lines, as Mission Planner
// saves and loads .param files (MAVProxy's `param load` reads it too). Values at 9 significant
// digits (the parameters are floats).
//
// Cannot hold: the misalignment (ArduPilot's accelerometer calibration stores only offsets and
// diagonal scales: its AccelCalibrator fits off-diagonal terms but AP_InertialSensor saves only
// offset and diagonal), and the sensor effects (ArduPilot's own temperature calibration,
// INS_TCALn_*, is a polynomial learnt on board, not this model's terms). Values outside the
// documented ranges (INS_ACCOFFS_* -3.5..3.5 m/s/s, INS_ACCSCAL_* 0.8..1.2; AP_InertialSensor.cpp
// @Range) are written and reported in `notes`: the nominal scale or zero-g level is then
// probably wrong.
#pragma once

#include "accelcal/io/export/diagonal_correction.h"
#include "accelcal/io/export/export_result.h"

namespace accelcal {

// Throws accelcal::Error when `driver` is invalid or an effect is unknown.
ExportResult ExportArduPilotParams(const Calibration& cal, const DriverScaleOptions& driver,
                                   const ExportContext& context);

}  // namespace accelcal

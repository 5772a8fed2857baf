// Exports of a calibration (calibration_file.h) to the formats other tools read: a C header for
// firmware, ArduPilot and PX4 parameter files, Kalibr's imu.yaml, CSV. One file per target; all
// share what is here.
//
// Honesty contract: every exporter returns, beside the text, what of the calibration its target
// cannot hold (`cannot_hold`: the user must know the exported correction is not the whole
// calibration) and other facts the user needs (`notes`: conventions assumed, values outside
// what the target accepts). Nothing is dropped silently.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/calibration/calibration.h"

namespace accelcal {

struct ExportResult {
  std::string text;                      // the file's whole content
  std::vector<std::string> cannot_hold;  // parts of the calibration the target cannot represent
  std::vector<std::string> notes;        // conventions, ranges, what to do next
};

// Where the calibration came from, for the comment at the top of an exported file. Every field
// may be empty ("unknown" is written then).
struct ExportContext {
  std::string device;    // serial of the calibrated device
  std::string date_utc;  // when the calibration was made, ISO 8601
  std::string source;    // the calibration file or session read; defaults to Calibration::source
};

// The 3x3 matrix M of a^p = M (raw - b): M = T K^-1 (sensor_model.h), m/s^2 per count.
Eigen::Matrix3d CorrectionMatrix(const SensorModel& model);

// The adopted effects that are properties of the sensor (CorrectsReadings: apply corrects every
// reading with them), by name, in correction order (effect.h, CorrectsBefore). Throws
// accelcal::Error for an effect this version does not know.
std::vector<std::string> SensorEffectNames(const Calibration& cal);
// One note per adopted effect of the calibration session (radius, speed, size effect, drift):
// not a property of the sensor's readings, so no export carries it (as in `accelcal apply`).
std::vector<std::string> SessionEffectNotes(const Calibration& cal);
// Parameter `key` of adopted effect `name` (throws accelcal::Error when missing or not finite).
double EffectParameterValue(const Calibration& cal, const std::string& name, const std::string& key);
// The effects' reference temperature, degC (throws when the calibration lacks it).
double EffectReferenceTempC(const Calibration& cal);

// A number as the shortest text that reads back to the same double ("0.1", "2048.25", "1e-05").
// Throws accelcal::Error for a value that is not finite: no export ever holds inf or nan.
std::string ExportNumber(double value);
// The same with 9 significant digits (a float's round trip: the flight stacks store REAL32).
std::string ExportNumber9(double value);
// "device D, calibrated DATE, from SOURCE" with "unknown" for empty fields, on one line whatever
// the fields hold (base/safe_text.h, DisplayText: a line break or a control character in a
// typed device name becomes an escape), so it can go into any exported file's comment.
std::string DescribeOrigin(const Calibration& cal, const ExportContext& context);

}  // namespace accelcal

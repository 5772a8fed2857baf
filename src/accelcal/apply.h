// Applying a calibration to raw samples: a^p = T K^-1 (raw - b), m/s^2 (sensor_model.h).
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

#include <Eigen/Core>

#include "accelcal/error.h"
#include "accelcal/io/calibration_file.h"

namespace accelcal {

// Throws accelcal::Error when `cal` lists an effect this version cannot apply: applying the
// base model alone would give silently wrong numbers.
void CheckApplicable(const Calibration& cal);

// The calibrated specific force of one raw reading, m/s^2 (platform frame).
Eigen::Vector3d ApplyCalibration(const Calibration& cal, const Sample& sample);

struct ApplyStreamResult {
  long lines = 0;      // lines read
  long samples = 0;    // data lines written calibrated
  long malformed = 0;  // lines reported to on_error and skipped
};

// Reads lines `t ax ay az [temp_c]` (the sample protocol: blanks or commas, '#' comments) from
// `in` and writes `t ax ay az [temp_c]` with ax ay az in m/s^2 to `out`; comments are passed
// through. A malformed line goes to `on_error` and is skipped; the stream goes on.
ApplyStreamResult ApplyStream(std::istream& in, std::ostream& out, const Calibration& cal,
                              const std::string& source_name,
                              const std::function<void(const InputError&)>& on_error);

}  // namespace accelcal

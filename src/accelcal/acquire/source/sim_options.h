// How the live simulated bench (SimSource) behaves: its pace against the wall clock and the
// imperfections of the person placing the sensor.
#pragma once

#include <string>

#include "accelcal/base/capture.h"

namespace accelcal {

struct SimOptions {
  // Simulated seconds per wall-clock second: 1 = real time, 50 = a whole session in seconds.
  // 0 = as fast as possible (each Read delivers fast_chunk_s of simulated time; for tests).
  double speed = 1.0;
  // speed 0: simulated time delivered per Read call, s.
  double fast_chunk_s = 1.0;
  // Std of each component of the random rotation added to every placement, deg.
  // NaN => the scenario's [bench] placement_error_deg.
  double placement_error_deg = kNaN;
  // Chance that a placement is followed by a bump (a knock on the bench) while the sensor
  // should be still, per placement, 0..1.
  double bump_probability = 0.1;
  // After a placement the sensor moves this long (turned into place, then a hand letting go,
  // jitter dying away) before it is still, s. 0 => it jumps to the pose.
  double settle_s = 1.5;

  // Empty when valid; otherwise what is wrong.
  std::string Validate() const;
};

}  // namespace accelcal

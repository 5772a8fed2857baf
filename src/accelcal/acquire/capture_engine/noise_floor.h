// The sensor's noise floor: the per-axis standard deviation of raw_counts when the sensor is
// perfectly still, counts. The stability checks judge a window against it ("x std 4.1 counts,
// limit 2.5" where the limit is a multiple of the floor).
//
// Where it comes from, in order of preference:
//   - a quiet period at the start of a session, the sensor left alone on the table
//     (FromQuietPeriod over its CaptureStats);
//   - given (a datasheet's noise density times the bandwidth, or an earlier session);
//   - offline, from the captures of a set themselves (FromCaptures: the median over the
//     captures of each axis' std, so one bumped capture cannot raise it).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"

namespace accelcal {

struct NoiseFloor {
  // The fewest samples a quiet period gives a floor from: a std of n samples is known within
  // about 1 / sqrt(2 (n - 1)) of itself, 7 % at 100. A floor from a handful (8 samples of a
  // vehicle still at its 4 Hz default, before the rate asked took effect) came out at half the
  // sensor's noise, and every still pose after it was then called shaking (1.5 x that floor).
  static constexpr long kMinQuietSamples = 100;

  Eigen::Vector3d std_counts = Eigen::Vector3d::Constant(kNaN);  // per axis, counts
  std::string source;  // where it came from, for reports ("quiet period of 2.0 s", "given", ...)

  // From the statistics of a quiet period (at least 2 samples). The period is trusted to be
  // still: measure it before anything else happens on the bench.
  static NoiseFloor FromQuietPeriod(const CaptureStats& quiet);
  static NoiseFloor Given(const Eigen::Vector3d& std_counts);
  // Median over `captures` (those with used() and at least 2 finite samples) of each axis' std.
  // NaN per axis when there is no such capture.
  static NoiseFloor FromCaptures(const std::vector<Capture>& captures);

  // Empty when usable: finite and >= 0 on every axis. (0 is allowed: a quantized noise-free
  // signal; the stability options keep an absolute minimum limit for that case.)
  std::string Validate() const;
};

}  // namespace accelcal

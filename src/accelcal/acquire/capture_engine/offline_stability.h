// The static stability check applied offline to a capture set: a static capture that was not
// still (a bump, a hand on the table, drift) is left out of the fit with its reason, as
// screening does for NaN and clipping. Same check as the live engine (static_stability.h).
//
// The noise floor is given, or estimated from the set itself: the median over its static
// captures of each axis' std (noise_floor.h), so a few unstable captures cannot raise it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/acquire/capture_engine/noise_floor.h"
#include "accelcal/acquire/capture_engine/static_stability.h"

namespace accelcal {

struct OfflineStabilityOptions {
  StaticStabilityOptions stability;
  // Per-axis noise std, counts; nullopt: estimated from the set's static captures.
  std::optional<Eigen::Vector3d> noise_floor_counts;

  std::string Validate() const;
};

// Judges every static capture with used() == true; one that is not stable gets
// rejection_reason "not still: <the verdict's reason>" (e.g. "not still: spike: y jumped 41
// counts (9.2 sigma) at t = 12.34 s"). Turntable captures and captures already left out are
// not touched. Returns the noise floor used (NaN when there was no usable static capture to
// judge). Throws accelcal::Error when the options are not valid.
NoiseFloor ScreenStaticStability(std::vector<Capture>& captures,
                                 const OfflineStabilityOptions& options);

}  // namespace accelcal

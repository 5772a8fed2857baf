// Per-axis variance over a centred sliding window, in O(n) for the whole recording.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"

namespace accelcal::detail {

// For each sample i whose centred window [i - h, i + h] (h = window_samples / 2) lies inside the
// recording: the per-axis sample variance (n - 1 denominator) of raw_counts over that window,
// counts^2. Samples closer than h to either end get NaN. window_samples must be odd and >= 3;
// the samples must be finite.
//
// The window statistics are detail::WindowSums (shared with the stability check of captures),
// kept relative to a sample of the current window and rebuilt from scratch every few thousand
// steps so that neither rounding drift nor a far-moved signal can build up.
std::vector<Eigen::Vector3d> SlidingWindowVariance(const std::vector<Sample>& samples,
                                                   int window_samples);

}  // namespace accelcal::detail

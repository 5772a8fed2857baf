#include "accelcal/acquire/static_detector.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "accelcal/acquire/detail/sliding_variance.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {

// Samples in the quiet start: t - t_first <= init_static_s.
long CountQuietSamples(const std::vector<Sample>& recording, double init_static_s) {
  const double t_end_s = recording.front().t_s + init_static_s;
  const auto past = std::upper_bound(recording.begin(), recording.end(), t_end_s,
                                     [](double t, const Sample& s) { return t < s.t_s; });
  return static_cast<long>(past - recording.begin());
}

// Norm of the per-axis sample variance of the first `count` samples, counts^2 (two passes:
// no cancellation).
double VarianceNorm(const std::vector<Sample>& recording, long count) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (long i = 0; i < count; ++i) mean += recording[static_cast<size_t>(i)].raw_counts;
  mean /= static_cast<double>(count);
  Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero();
  for (long i = 0; i < count; ++i) {
    sum_sq += (recording[static_cast<size_t>(i)].raw_counts - mean).cwiseAbs2();
  }
  return (sum_sq / static_cast<double>(count - 1)).norm();
}

void CheckLengths(const std::vector<Sample>& recording, const StaticDetectorOptions& options,
                  long quiet_samples) {
  const long n = static_cast<long>(recording.size());
  if (n < options.window_samples) {
    throw Error(fmt::format("static detection: the recording has {} samples, fewer than one "
                            "window ({} samples)", n, options.window_samples));
  }
  const double duration_s = recording.back().t_s - recording.front().t_s;
  if (duration_s < options.init_static_s) {
    throw Error(fmt::format("static detection: the recording lasts {:.3g} s, shorter than its "
                            "quiet start (init_static_s = {} s)", duration_s,
                            options.init_static_s));
  }
  if (quiet_samples < options.window_samples) {
    throw Error(fmt::format("static detection: the quiet start ({} s) holds {} samples, fewer "
                            "than one window ({}); lengthen init_static_s", options.init_static_s,
                            quiet_samples, options.window_samples));
  }
}

double MedianOfFinite(const std::vector<double>& values) {
  std::vector<double> finite;
  finite.reserve(values.size());
  for (const double v : values) {
    if (std::isfinite(v)) finite.push_back(v);
  }
  const auto middle = finite.begin() + static_cast<long>(finite.size() / 2);
  std::nth_element(finite.begin(), middle, finite.end());
  return *middle;
}

void CheckQuietStart(double quiet_norm, double median_norm, const StaticDetectorOptions& options) {
  if (!(quiet_norm > 0.0)) {
    throw Error(fmt::format("static detection: the quiet start (first {} s) has zero variance "
                            "(noise-free or stuck data), so no threshold can be derived",
                            options.init_static_s));
  }
  if (quiet_norm > options.max_quiet_to_median_ratio * median_norm) {
    throw Error(fmt::format(
        "static detection: the quiet start (first {} s) is not quiet: its variance norm, "
        "{:.4g} counts^2, is {:.3g} times the median window's ({:.4g} counts^2); the sensor "
        "must be still from the start of the recording for init_static_s (shorten it if the "
        "still start is shorter)", options.init_static_s, quiet_norm,
        quiet_norm / median_norm, median_norm));
  }
}

// Runs of consecutive `is_static` samples at least `min_samples` long.
std::vector<StaticInterval> StaticRuns(const std::vector<Sample>& recording,
                                       const std::vector<bool>& is_static, long min_samples) {
  std::vector<StaticInterval> intervals;
  const long n = static_cast<long>(is_static.size());
  long i = 0;
  while (i < n) {
    if (!is_static[static_cast<size_t>(i)]) {
      ++i;
      continue;
    }
    long last = i;
    while (last + 1 < n && is_static[static_cast<size_t>(last + 1)]) ++last;
    if (last - i + 1 >= min_samples) {
      intervals.push_back({i, last, recording[static_cast<size_t>(i)].t_s,
                           recording[static_cast<size_t>(last)].t_s});
    }
    i = last + 1;
  }
  return intervals;
}

}  // namespace

std::string StaticDetectorOptions::Validate() const {
  if (!(std::isfinite(init_static_s) && init_static_s > 0.0)) {
    return fmt::format("init_static_s is {}, must be > 0 s", init_static_s);
  }
  if (window_samples < 3 || window_samples % 2 == 0) {
    return fmt::format("window_samples is {}, must be odd and >= 3", window_samples);
  }
  if (!(std::isfinite(threshold_multiplier) && threshold_multiplier > 0.0)) {
    return fmt::format("threshold_multiplier is {}, must be > 0", threshold_multiplier);
  }
  if (min_interval_samples < 1) {
    return fmt::format("min_interval_samples is {}, must be >= 1", min_interval_samples);
  }
  if (!(max_quiet_to_median_ratio > 1.0)) {
    return fmt::format("max_quiet_to_median_ratio is {}, must be > 1", max_quiet_to_median_ratio);
  }
  return {};
}

StaticDetection DetectStaticIntervals(const std::vector<Sample>& recording,
                                      const StaticDetectorOptions& options) {
  if (const std::string problem = options.Validate(); !problem.empty()) {
    throw Error("static detector options: " + problem);
  }
  if (recording.empty()) throw Error("static detection: the recording is empty");
  const long quiet_samples = CountQuietSamples(recording, options.init_static_s);
  CheckLengths(recording, options, quiet_samples);

  StaticDetection detection;
  detection.quiet_variance_norm_counts2 = VarianceNorm(recording, quiet_samples);
  const std::vector<Eigen::Vector3d> variance =
      detail::SlidingWindowVariance(recording, options.window_samples);
  std::vector<double> norms(variance.size());
  for (size_t i = 0; i < variance.size(); ++i) norms[i] = variance[i].norm();  // NaN at the ends
  CheckQuietStart(detection.quiet_variance_norm_counts2, MedianOfFinite(norms), options);

  detection.threshold_counts2 =
      options.threshold_multiplier * detection.quiet_variance_norm_counts2;
  std::vector<bool> is_static(norms.size());
  for (size_t i = 0; i < norms.size(); ++i) is_static[i] = norms[i] < detection.threshold_counts2;
  detection.intervals = StaticRuns(recording, is_static, options.min_interval_samples);
  return detection;
}

std::vector<Capture> CapturesFromIntervals(const std::vector<Sample>& recording,
                                           const StaticDetection& detection) {
  std::vector<Capture> captures;
  captures.reserve(detection.intervals.size());
  for (const StaticInterval& interval : detection.intervals) {
    if (interval.first_index < 0 || interval.last_index < interval.first_index ||
        interval.last_index >= static_cast<long>(recording.size())) {
      throw Error(fmt::format("static interval {}..{} lies outside the recording ({} samples)",
                              interval.first_index, interval.last_index, recording.size()));
    }
    Capture& capture = captures.emplace_back();
    capture.id = static_cast<int>(captures.size());
    capture.kind = CaptureKind::kStatic;
    capture.label = fmt::format("static {:.1f}-{:.1f} s", interval.t_start_s, interval.t_end_s);
    capture.samples.assign(recording.begin() + interval.first_index,
                           recording.begin() + interval.last_index + 1);
  }
  return captures;
}

}  // namespace accelcal

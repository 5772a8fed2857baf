#include "accelcal/calibration/capture_screening.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "accelcal/base/text_scan.h"
#include "accelcal/base/error.h"
#include "accelcal/calibration/turntable_plausibility.h"

namespace accelcal {
namespace {

constexpr std::array<char, 3> kAxisNames = {'x', 'y', 'z'};
constexpr int kMinRailBits = 8;
constexpr int kMaxRailBits = 32;

bool IsFiniteSample(const Sample& s) { return std::isfinite(s.t_s) && s.raw_counts.allFinite(); }

bool IsHighRail(double v) {
  for (int n = kMinRailBits; n <= kMaxRailBits; ++n) {
    if (v == std::ldexp(1.0, n) - 1.0 || v == std::ldexp(1.0, n - 1) - 1.0) return true;
  }
  return false;
}

bool IsLowRail(double v) {
  if (v == 0.0) return true;
  for (int n = kMinRailBits; n <= kMaxRailBits; ++n) {
    if (v == -std::ldexp(1.0, n - 1)) return true;
  }
  return false;
}

std::string NonFiniteReason(const Capture& capture) {
  long count = 0;
  double first_t_s = kNaN;
  for (const Sample& s : capture.samples) {
    if (IsFiniteSample(s)) continue;
    if (count++ == 0) first_t_s = s.t_s;
  }
  if (count == 0) return {};
  return fmt::format("{} sample{} NaN or infinite (first at t = {} s)", count,
                     count == 1 ? " is" : "s are", detail::FormatNumber(first_t_s));
}

// Finite samples of `axis` at or beyond `limit` (below it when `low`, above it otherwise).
long CountAtLimit(const Capture& capture, int axis, double limit, bool low) {
  long count = 0;
  for (const Sample& s : capture.samples) {
    if (!IsFiniteSample(s)) continue;
    const double v = s.raw_counts[axis];
    if (low ? v <= limit : v >= limit) ++count;
  }
  return count;
}

long CountFinite(const Capture& capture) {
  long count = 0;
  for (const Sample& s : capture.samples) count += IsFiniteSample(s) ? 1 : 0;
  return count;
}

std::vector<std::string> KnownRangeClipping(const Capture& capture, const AdcRange& range) {
  std::vector<std::string> reasons;
  const long n = CountFinite(capture);
  for (int axis = 0; axis < 3; ++axis) {
    for (const bool low : {true, false}) {
      const double limit = low ? range.min_counts : range.max_counts;
      const long count = CountAtLimit(capture, axis, limit, low);
      if (count == 0) continue;
      reasons.push_back(fmt::format("{} clipped at the ADC limit {} counts in {} of {} samples",
                                    kAxisNames[axis], detail::FormatNumber(limit), count, n));
    }
  }
  return reasons;
}

std::vector<std::string> InferredRailClipping(const Capture& capture, double rail_fraction) {
  std::vector<std::string> reasons;
  const CaptureStats& stats = capture.stats();  // min/max over finite samples
  if (stats.n == 0) return reasons;
  const double needed = std::max(2.0, rail_fraction * static_cast<double>(stats.n));
  for (int axis = 0; axis < 3; ++axis) {
    for (const bool low : {true, false}) {
      const double extreme = low ? stats.min_counts[axis] : stats.max_counts[axis];
      if (!(low ? IsLowRail(extreme) : IsHighRail(extreme))) continue;
      const long count = CountAtLimit(capture, axis, extreme, low);
      if (static_cast<double>(count) < needed) continue;
      reasons.push_back(fmt::format(
          "{} clipped at {} counts (a typical ADC rail; the range is not known) in {} of {} "
          "samples", kAxisNames[axis], detail::FormatNumber(extreme), count, stats.n));
    }
  }
  return reasons;
}

}  // namespace

std::string ScreeningOptions::Validate() const {
  if (min_samples < 2) return fmt::format("min_samples is {}, must be at least 2", min_samples);
  if (adc_range) {
    if (!std::isfinite(adc_range->min_counts) || !std::isfinite(adc_range->max_counts) ||
        !(adc_range->min_counts < adc_range->max_counts)) {
      return fmt::format("adc_range {}..{} counts: limits must be finite with min < max",
                         adc_range->min_counts, adc_range->max_counts);
    }
  }
  if (!(rail_fraction > 0.0 && rail_fraction <= 1.0)) {
    return fmt::format("rail_fraction is {}, must be in (0, 1]", rail_fraction);
  }
  return {};
}

std::string ScreeningReason(const Capture& capture, const ScreeningOptions& options) {
  std::vector<std::string> reasons;
  const long n = static_cast<long>(capture.samples.size());
  if (n < options.min_samples) {
    reasons.push_back(fmt::format("{} sample{}, at least {} needed", n, n == 1 ? "" : "s",
                                  options.min_samples));
  }
  if (std::string non_finite = NonFiniteReason(capture); !non_finite.empty()) {
    reasons.push_back(std::move(non_finite));
  }
  const std::vector<std::string> clipping =
      options.adc_range ? KnownRangeClipping(capture, *options.adc_range)
                        : InferredRailClipping(capture, options.rail_fraction);
  reasons.insert(reasons.end(), clipping.begin(), clipping.end());
  if (capture.kind == CaptureKind::kTurntable) {
    if (std::string problem = TurntableConditionsProblem(capture.radius_m, capture.rpm); !problem.empty())
      reasons.push_back(std::move(problem));
  }
  return fmt::format("{}", fmt::join(reasons, "; "));
}

void ScreenCaptures(std::vector<Capture>& captures, const ScreeningOptions& options) {
  if (const std::string problem = options.Validate(); !problem.empty()) {
    throw Error("screening options: " + problem);
  }
  for (Capture& capture : captures) capture.rejection_reason = ScreeningReason(capture, options);
}

}  // namespace accelcal

#include "accelcal/calibration/capture_stop_rule.h"

#include <algorithm>
#include <cmath>

namespace accelcal {
namespace {

long CeilSamples(double s, double rate_hz) {
  return std::max(1L, static_cast<long>(std::ceil(s * rate_hz - 1e-9)));
}

}  // namespace

CaptureStopRule CaptureStopRule::For(double planned_s, double rate_hz, double min_capture_s,
                                     double max_capture_s, double rpm) {
  CaptureStopRule rule;
  rule.min_samples = CeilSamples(min_capture_s, rate_hz);
  rule.max_samples = std::max(rule.min_samples, CeilSamples(max_capture_s, rate_hz));
  long needed = std::clamp(CeilSamples(planned_s, rate_hz), rule.min_samples, rule.max_samples);
  if (rpm > 0.0) {
    const double per_revolution = rate_hz * 60.0 / rpm;
    const auto whole = [&](long n) { return std::ceil(n / per_revolution - 1e-9) * per_revolution; };
    rule.min_samples = static_cast<long>(std::ceil(whole(rule.min_samples) - 1e-9));
    const double max_turns = std::floor(rule.max_samples / per_revolution + 1e-9);
    if (max_turns * per_revolution >= rule.min_samples)
      rule.max_samples = static_cast<long>(std::ceil(max_turns * per_revolution - 1e-9));
    else
      rule.max_samples = rule.min_samples;
    needed = std::clamp(static_cast<long>(std::ceil(whole(needed) - 1e-9)), rule.min_samples, rule.max_samples);
  }
  rule.needed_samples = needed;
  return rule;
}

double CaptureStopRule::Progress(long samples) const {
  if (needed_samples <= 0) return 1.0;
  return std::clamp(static_cast<double>(samples) / static_cast<double>(needed_samples), 0.0, 1.0);
}

double CaptureStopRule::RemainingS(long samples, double rate_hz) const {
  return std::max(0L, needed_samples - samples) / rate_hz;
}

}  // namespace accelcal

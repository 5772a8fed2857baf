#include "accelcal/acquire/capture_engine/capture_request.h"

#include <cmath>

#include <fmt/format.h>

namespace accelcal {

std::string CaptureRequest::Validate() const {
  if (id <= 0) return fmt::format("capture id is {}, must be > 0", id);
  if (!(std::isfinite(duration_s) && duration_s > 0.0))
    return fmt::format("duration_s is {}, must be > 0 s", duration_s);
  if (!(std::isfinite(timeout_s) && timeout_s > duration_s))
    return fmt::format("timeout_s is {} s, must be longer than the capture ({} s)", timeout_s,
                       duration_s);
  if (stop_samples < 0) return fmt::format("stop_samples is {}, must be >= 0 (0: by duration_s)", stop_samples);
  if (!(std::isfinite(settle_wait_s) && settle_wait_s >= 0.0))
    return fmt::format("settle_wait_s is {}, must be >= 0 s", settle_wait_s);
  if (kind == CaptureKind::kTurntable) return turntable.Validate();
  if (!(expected.up.allFinite() && expected.up.norm() > 0.0))
    return "the expected up direction must be a finite, non-zero vector";
  return {};
}

std::string CaptureContext::Validate() const {
  if (std::string e = rough_model.Validate(); !e.empty()) return "rough model: " + e;
  return noise_floor.Validate();
}

}  // namespace accelcal

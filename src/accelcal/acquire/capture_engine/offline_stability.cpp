#include "accelcal/acquire/capture_engine/offline_stability.h"

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

std::vector<Capture> UsableStatic(const std::vector<Capture>& captures) {
  std::vector<Capture> out;
  for (const Capture& c : captures) {
    if (c.used() && c.kind == CaptureKind::kStatic) out.push_back(c);
  }
  return out;
}

}  // namespace

std::string OfflineStabilityOptions::Validate() const {
  if (std::string e = stability.Validate(); !e.empty()) return e;
  if (noise_floor_counts) return NoiseFloor::Given(*noise_floor_counts).Validate();
  return {};
}

NoiseFloor ScreenStaticStability(std::vector<Capture>& captures,
                                 const OfflineStabilityOptions& options) {
  if (std::string e = options.Validate(); !e.empty()) throw Error("stability check: " + e);
  const std::vector<Capture> usable = UsableStatic(captures);
  if (usable.empty()) return NoiseFloor{};  // nothing to judge
  const NoiseFloor floor = options.noise_floor_counts
                               ? NoiseFloor::Given(*options.noise_floor_counts)
                               : NoiseFloor::FromCaptures(usable);
  for (Capture& capture : captures) {
    if (!capture.used() || capture.kind != CaptureKind::kStatic) continue;
    const StabilityVerdict verdict =
        EvaluateStaticStability(capture.samples, floor, options.stability);
    // A capture too short to judge is screening's business (min_samples), not this check's.
    if (verdict.judged && !verdict.stable) capture.rejection_reason = "not still: " + verdict.reason;
  }
  return floor;
}

}  // namespace accelcal

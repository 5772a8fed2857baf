#include "accelcal/acquire/sim/technician.h"

#include <algorithm>
#include <cmath>

namespace accelcal::sim {
namespace {

bool Matches(const Mistake& m, const CapturePlan& asked) {
  if (m.static_request()) {
    return asked.kind == CaptureKind::kStatic && (asked.up.normalized() - *m.asked_up).norm() < 1e-6;
  }
  return asked.kind == CaptureKind::kTurntable && asked.radial_axis == *m.asked_radial &&
         asked.up_axis == *m.asked_up_axis &&
         (std::isnan(m.asked_radius_m) || std::abs(asked.radius_m - m.asked_radius_m) < 1e-9);
}

}  // namespace

TechnicianPlay::TechnicianPlay(Technician spec)
    : spec_(std::move(spec)), matches_(spec_.mistakes.size(), 0) {}

Deed TechnicianPlay::Place(const CapturePlan& asked) {
  Deed deed;
  deed.placed = asked;
  bool decided = false;
  for (size_t i = 0; i < spec_.mistakes.size(); ++i) {
    const Mistake& m = spec_.mistakes[i];
    if (!Matches(m, asked)) continue;
    const int seen = matches_[i]++;
    if (decided || seen < m.after || seen >= m.after + m.times) continue;
    decided = true;
    if (m.up) deed.placed.up = *m.up;
    if (m.radial) deed.placed.radial_axis = *m.radial;
    if (m.up_axis) deed.placed.up_axis = *m.up_axis;
    if (!std::isnan(m.radius_m)) deed.placed.radius_m = m.radius_m;
    deed.bump_at_s = m.bump_at_s;
    deed.bump_peak_mps2 = m.bump_peak_mps2;
    deed.bump_duration_s = m.bump_duration_s;
  }
  return deed;
}

double TechnicianPlay::ShakeRmsAt(double t_s) const {
  double rms = 0.0;
  for (const Shake& s : spec_.shakes)
    if (t_s >= s.from_s && t_s < s.to_s) rms = std::max(rms, s.rms_mps2);
  return rms;
}

}  // namespace accelcal::sim

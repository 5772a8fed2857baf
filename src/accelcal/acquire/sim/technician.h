// The technician at the live virtual bench (scenario [technician]): the person the wizard talks
// to, who places the sensor as asked, except when the scenario says otherwise. TechnicianPlay
// decides, placement by placement, what is really put on the bench (a wrong face, a wrong
// mounting or radius, a knock after settling: Mistake) and when the bench shakes (Shake). The
// leveling (the feet adjusted after the wizard's advice) is the bench's (VirtualBench).
#pragma once

#include <vector>

#include "accelcal/acquire/sim/scenario.h"

namespace accelcal::sim {

// What the technician does for one request.
struct Deed {
  CapturePlan placed;  // the pose or mounting really placed
  // A knock on the bench this long after the sensor settles, s (NaN: none), its peak (m/s^2,
  // horizontal) and length (s).
  double bump_at_s = kNaN;
  double bump_peak_mps2 = 0.0;
  double bump_duration_s = 0.1;
};

class TechnicianPlay {
 public:
  explicit TechnicianPlay(Technician spec);

  // The deed for `asked` (a static pose or a turntable mounting as the wizard asked for it);
  // counts the request against every mistake that matches it. The first matching mistake in
  // its active stretch (after `after` matches, for `times` of them) decides.
  Deed Place(const CapturePlan& asked);
  // White acceleration of the bench at t_s (sim clock), m/s^2 per axis: the largest shake
  // active then, 0 when none.
  double ShakeRmsAt(double t_s) const;
  const Technician& spec() const { return spec_; }

 private:
  Technician spec_;
  std::vector<int> matches_;  // per mistake: requests matched so far
};

}  // namespace accelcal::sim

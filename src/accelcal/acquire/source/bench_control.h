// The controls of the simulated bench: what the person at the bench does when the wizard asks
// for a pose. Only the simulator has them (SampleSource::bench() is nullptr for real sources).
//
// Frames and units as in sim/scenario.h: `up` is the direction of world-up (the specific force
// at rest) in the sensor's platform frame; radius in m, speed in rpm. Each placement lands with
// the bench's placement error, moves for settle_s (turned into place, a hand letting go) before
// the sensor is still, and now and then is followed by a bump (SimOptions).
#pragma once

#include <Eigen/Core>

#include "accelcal/acquire/sim/scenario.h"

namespace accelcal {

class BenchControl {
 public:
  virtual ~BenchControl() = default;

  // Sets the sensor down in a static pose with `up_platform` pointing up, turned `yaw_rad` about
  // the vertical from its usual heading (pi: the second reading of the leveling reversal).
  // Throws accelcal::Error when up_platform is zero or not finite.
  virtual void PlaceStatic(const Eigen::Vector3d& up_platform, double yaw_rad) = 0;
  // Mounts the sensor on the turntable at radius_m from the axis, `radial` pointing outward and
  // `up` along the spin axis, and runs the table at rpm. Throws accelcal::Error when radial is
  // parallel to up, or radius or rpm is not positive.
  virtual void PlaceTurntable(double radius_m, double rpm, sim::SensorAxis radial,
                              sim::SensorAxis up) = 0;
  // Stops the table; the sensor stays mounted, resting with its `up` axis up.
  virtual void StopTurntable() = 0;
  // The person follows the wizard's leveling advice for the measured tilt of the table
  // (`tilt_deg`: about x, about y, leveling.h's convention) by turning its feet.
  virtual void AdjustTableFeet(const Eigen::Vector2d& tilt_deg) = 0;
  // The person levels the turntable (a spirit level on its plate, its feet turned) after the
  // wizard refused a run for the table's tilt.
  virtual void LevelTurntable() = 0;
  // The simulated clock: t of the next sample, s.
  virtual double now_s() const = 0;
};

}  // namespace accelcal

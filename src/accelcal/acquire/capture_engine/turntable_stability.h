// Is the turntable run what the operator entered? Checked on a window of samples (the last
// seconds while the table spins up, then the whole capture) through a rough model (a datasheet
// scale and bias, or the static captures' fit), before the capture is accepted:
//
//   f_k = rough_model.Calibrate(raw_k)     specific force, platform frame, m/s^2
//   expected centripetal   c = w^2 r,  w = rpm 2 pi / 60 (entered rpm and radius)
//   measured centripetal   c_m = |mean f - (mean f . up) up|   (the horizontal part of the mean;
//                          the mean over whole revolutions cancels the tilt wobble)
//
// 0. Mounted as asked: the mean force is -c radial + g up for some pair of sensor axes (the
//    radial one carries the centripetal load, the up one gravity). Every perpendicular pair of
//    signed axes is tried, c fitted for each; the mounting asked for must explain the mean
//    within max(min_mounting_residual_mps2, 10 % of |mean f|) when another does better:
//      "wrong mounting: the samples show +y radial, +z up (the centripetal 15.8 m/s^2 is on y),
//       not +x radial, +z up: mount the sensor with +x pointing away from the spin axis and +z
//       up"
// 1. Consistent: |c_m / c - 1| <= centripetal_tolerance. A mismatch says what is likely:
//      "radius looks 100x too large: 10 m entered; did you mean 0.1 m?"   (ratio near 10^-k or
//      10^k, k = 1..3: a unit slip), else
//      "centripetal 15.8 m/s^2 expected from 120 rpm at 0.1 m, 3.9 measured: check rpm and
//       radius (the measurement fits 60 rpm at 0.1 m)".
// 2. Steady speed: the radial component f . radial, less the once-per-revolution wobble (a sine
//    at the entered speed, least squares), averaged over `sub_windows` equal stretches of time;
//    max - min of those means <= max(speed_tolerance x c, min_speed_spread_mps2).
//      "speed not steady: centripetal went from 14.2 to 15.9 m/s^2 across the window (11 %),
//       limit 3 %"
// 3. Tilt: a spin axis tilted by theta turns gravity's horizontal part g sin(theta) once per
//    revolution in the table frame. A sine at the stated speed is fitted to each axis's counts
//    (OncePerRevolution: amplitude and phase, least squares); the swing's amplitude A (in
//    m/s^2 through the rough scale: the rotating vector shows on the axes of the table's plane,
//    so A^2 = sum of the axes' squared amplitudes / 2) gives theta = asin(A / g). Reported, and
//    tolerated up to max_tilt_deg:
//      "the turntable is tilted 3.1 deg (gravity swings 0.53 m/s^2 once per revolution),
//       tolerance 2 deg: level the turntable (a spirit level on its plate, turn its feet)"
//    An accepted capture has the swing removed from its samples (RemoveOncePerRevolution), so
//    that its noise, and the weight the fit gives it, are the sensor's, not the tilt's.
//    With judge_tilt false (a window that may still hold the hand's shake) the tilt is
//    measured but not judged.
// 4. Still: no reading further than spike_sigmas robust sigmas (1.4826 x the median absolute
//    deviation) from the run's model, its mean plus the swing, on any axis: a knock on the
//    bench (which would also read as a swing) makes the run unsteady, retried.
//      "knocked: y jumped 41 counts (12 sigma) from the run at t = 12.34 s"
// Before a run, CheckTurntablePlan compares the planned specific force with the sensor's range.
//
// Units: m, rpm (as entered), m/s^2, deg for the tilt shown to the operator.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/base/capture_set.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

struct TurntableStabilityOptions {
  // Local gravity, m/s^2 (the rough check needs no better than 0.1 %).
  double gravity_mps2 = 9.80665;
  // Largest relative mismatch of the measured centripetal part with w^2 r; (0, 1). Covers the
  // rough model's scale error (a few %) and a radius measured to a few mm.
  double centripetal_tolerance = 0.10;
  // Largest spread of the sub-windows' centripetal means, relative to w^2 r; > 0.
  double speed_tolerance = 0.03;
  // ... but never below this, m/s^2 (the noise of a short sub-window); >= 0.
  double min_speed_spread_mps2 = 0.05;
  // Number of stretches the window is cut into for the steadiness check; >= 2.
  int sub_windows = 4;
  // Largest tolerated tilt of the spin axis, deg; > 0.
  double max_tilt_deg = 2.0;
  // Check 0: a mounting explaining the mean this much better than the one asked for is a
  // wrong mounting (at least 10 % of |mean f|), m/s^2; > 0.
  double min_mounting_residual_mps2 = 1.0;
  // Check 3 decides (false: the tilt is measured and reported, never a failure).
  bool judge_tilt = true;
  // Check 4: a reading this many robust sigmas from the run's model is a knock; > 0.
  double spike_sigmas = 8.0;
  // CheckTurntablePlan: the planned force must stay this fraction inside the range; [0, 1).
  double range_margin = 0.05;

  std::string Validate() const;
};

// What the operator entered for a turntable run, and how the sensor is mounted.
struct TurntableSetup {
  double radius_m = kNaN;  // distance from the spin axis to the sensor, m (as entered)
  double rpm = kNaN;       // table speed, revolutions per minute (as entered)
  // Sensor axes (platform frame, unit vectors) pointing radially outward and up the spin axis.
  Eigen::Vector3d radial_axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up_axis = Eigen::Vector3d::UnitZ();

  std::string Validate() const;
  double ExpectedCentripetalMps2() const;  // w^2 r
};

// The once-per-revolution term of a run, per axis: raw_j(t) ~ c_j + cos_j cos(w (t - t0)) +
// sin_j sin(w (t - t0)), counts. All zero when the run spans less than one revolution.
struct OncePerRevolution {
  double t0_s = 0.0;
  double w_rad_per_s = 0.0;
  Eigen::Vector3d cos_counts = Eigen::Vector3d::Zero();
  Eigen::Vector3d sin_counts = Eigen::Vector3d::Zero();

  Eigen::Vector3d At(double t_s) const;  // the term at t_s, counts
};

struct TurntableVerdict {
  bool ok = false;
  bool mounted_as_asked = false;  // check 0
  std::string mounting_found;     // "+y radial, +z up": the best explaining mounting
  bool consistent = false;  // check 1
  bool steady = false;      // check 2
  bool level = false;       // check 3
  bool still = false;       // check 4 (counted in `steady`: a knocked run is retried)
  // Empty when ok; else every failed check in words, joined by "; ".
  std::string reason;

  long n_samples = 0;
  double expected_centripetal_mps2 = kNaN;  // w^2 r from the entered rpm and radius
  double measured_centripetal_mps2 = kNaN;  // c_m
  double centripetal_ratio = kNaN;          // c_m / (w^2 r)
  double mean_magnitude_mps2 = kNaN;        // |mean f|
  std::vector<double> sub_window_centripetal_mps2;  // check 2's means, in time order
  double speed_spread_fraction = kNaN;      // (max - min) of those / (w^2 r)
  double wobble_amplitude_mps2 = kNaN;      // A
  double tilt_deg = kNaN;                   // asin(A / g)
  OncePerRevolution swing;                  // check 3's fit
};

// `samples` less the swing (the finite ones; t unchanged).
void RemoveOncePerRevolution(std::vector<Sample>* samples, const OncePerRevolution& swing);

// The checks of the header comment over `samples` (finite ones; at least 3 and spanning some
// time). Throws accelcal::Error when options or setup are not valid.
TurntableVerdict EvaluateTurntable(const std::vector<Sample>& samples,
                                   const SensorModel& rough_model, const TurntableSetup& setup,
                                   const TurntableStabilityOptions& options);

// Empty when the planned specific force (-w^2 r along the radial axis, g along up) stays
// within the ADC range through the rough model on every axis; else, e.g.
// "planned 1579 m/s^2 on the radial axis exceeds the sensor's range on x (-58.9..59.4 m/s^2);
//  10 m is an unusual radius: did you mean 0.1 m?"
std::string CheckTurntablePlan(const TurntableSetup& setup, const SensorModel& rough_model,
                               const AdcRange& adc_range, const TurntableStabilityOptions& options);

}  // namespace accelcal

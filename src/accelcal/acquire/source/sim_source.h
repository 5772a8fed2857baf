// sim: the virtual bench as a live source. Samples come at the scenario's rate on a simulated
// clock (t from 0, continuous across placements), paced against the wall clock by
// SimOptions::speed (1 = real time, 50 = fifty times faster, 0 = as fast as asked). Through
// bench() a wizard places the sensor (BenchControl); each placement lands with a random
// placement error, moves for settle_s, and is sometimes followed by a bump. The scenario's
// [technician] plays the person at the bench (sim/technician.h): placements that go wrong on
// purpose, the bench shaking, the feet turned by a share of the advice.
//
// The truth stays with the scenario (scenario().sensor.model) and the current mounting
// (mounting()), so tests can compare what a calibration recovers with what was simulated.
// Initially the sensor rests level, +z up, still.
#pragma once

#include <functional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/acquire/source/sim_options.h"
#include "accelcal/acquire/source/status_tracker.h"
#include "accelcal/acquire/sim/technician.h"
#include "accelcal/acquire/sim/virtual_bench.h"

namespace accelcal {

class SimSource final : public SampleSource, public BenchControl {
 public:
  // Throws accelcal::Error when options.Validate() or scenario.Validate() complains.
  // dead_after_s and gap_factor as in SourceOptions.
  SimSource(sim::Scenario scenario, const SimOptions& options, double dead_after_s = 2.0,
            double gap_factor = 3.0);

  std::string Describe() const override { return "sim"; }
  ReadResult Read(double timeout_s, std::vector<Sample>* out) override;
  const SourceStatus& status() const override { return tracker_.status(); }
  BenchControl* bench() override { return this; }

  void PlaceStatic(const Eigen::Vector3d& up_platform, double yaw_rad) override;
  void PlaceTurntable(double radius_m, double rpm, sim::SensorAxis radial,
                      sim::SensorAxis up) override;
  void StopTurntable() override;
  void AdjustTableFeet(const Eigen::Vector2d& tilt_deg) override;
  void LevelTurntable() override;
  double now_s() const override;

  // The truth: the scenario the bench runs (sensor model, gravity, rate) and the current
  // mounting (placement error included).
  const sim::Scenario& scenario() const { return bench_.scenario(); }
  const sim::Mounting& mounting() const { return mounting_; }
  // The table and the turntable as they stand now (after the technician's leveling).
  const sim::VirtualBench& bench_state() const { return bench_; }
  // Bumps that have been scheduled so far (tests check the detector sees them).
  long bumps_scheduled() const { return bumps_scheduled_; }
  // Placements so far (the technician's, and the table stopping): a fixture's loose board
  // settles anew at each.
  long placements() const { return placements_; }

  // Called for each sample generated, before it is measured, with the specific force the
  // platform (a fixture's plate) feels at its reference point, in its frame, per sensing axis
  // (columns), m/s^2: the fixture bench measures it through each board (fixture_sim_source.h).
  using ForceTap = std::function<void(double t_s, const Eigen::Matrix3d& f_per_axis_mps2)>;
  void set_force_tap(ForceTap tap) { force_tap_ = std::move(tap); }

 private:
  struct JitterTone {
    double amplitude_mps2 = 0.0;
    double frequency_hz = 1.0;
    double phase_rad = 0.0;
  };

  void Place(const sim::CapturePlan& plan, bool settle);
  // What the technician places for `asked`, and the knock the scenario plays after it.
  void PlaceAsked(const sim::CapturePlan& asked);
  void ScheduleSettle(bool settle);
  void MaybeScheduleBump();
  void ScheduleBump(double at_s, double peak_mps2, double duration_s);
  long SamplesDue(double wall_now_s) const;
  Sample Generate(long k);
  Eigen::Vector3d JitterWorld(double t_s) const;
  Eigen::Vector3d ShakeWorld(double t_s);
  Eigen::Matrix3d PlatformToWorld(double t_s) const;

  SimOptions options_;
  sim::VirtualBench bench_;
  StatusTracker tracker_;
  std::mt19937_64 rng_;  // the operator's randomness (settling, bumps); the bench has its own
  std::mt19937_64 shake_rng_;  // the shaking bench's (a stream apart: no shake, no change)
  sim::TechnicianPlay technician_;
  sim::Mounting mounting_;
  Eigen::Quaterniond turn_from_;  // static: platform -> world before the latest placement
  double settle_start_s_ = 0.0;
  double settle_end_s_ = 0.0;     // the sensor is still (bumps aside) from here on, s
  std::vector<JitterTone> tones_;  // 3 per world axis
  long next_k_ = 0;                // index of the next sample on the simulated clock
  double wall_origin_s_;           // wall time at which sample 0 (t = 0) was due, s
  double last_burst_wall_s_ = -1e300;  // wall time of the last paced delivery, s
  long bumps_scheduled_ = 0;
  long placements_ = 0;
  ForceTap force_tap_;
};

}  // namespace accelcal

// The virtual bench's fixture as a live source (issue 31): one plate placed and mounted by the
// simulated technician exactly as the one-sensor bench places its sensor (sim_source.h: the same
// placements, settling, bumps, shaking and leveling), and on it the scenario's boards
// (sim/bench_fixture.h), each measuring the plate's specific force in its own axes, at its own
// offset (so its own turntable radius), through its own truth, with its own noise stream.
//
// Physics per board, at each sample of the plate's clock:
//   f_plate      the plate's specific force at its reference point, in its frame (SimSource's).
//   turntable    + the centripetal term of the board's offset: R^T (-w^2 (R o)_perp), R the
//                plate -> table rotation, o the offset, perp: without its spin-axis component.
//   mounting     f_board = M^T f_plate, M = mounted_to_plate (the board as really put in) times,
//                for a loose board, its tilt on the plate (drawn anew at each placement, each
//                component ~ N(0, loose_deg)) and a rocking about its three axes (a quarter of
//                loose_deg, 4-6 Hz) that dies out over its loose_rock_s after each placement (it goes
//                on moving after the plate has settled).
//   dead         no sample from dead_from_s on: its status goes dead, the others' stay up.
//
// Randomness: board i's noise from the bench seed and i alone (adding a board leaves the others'
// data as it was); its truth from FixtureTruths (the same seed).
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/acquire/sim/bench_fixture.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/acquire/source/sensor_set_source.h"
#include "accelcal/acquire/source/sim_source.h"
#include "accelcal/acquire/source/status_tracker.h"

namespace accelcal {

class FixtureSimSource final : public SensorSetSource {
 public:
  // `scenario` must have a [fixture] (sim/bench_fixture.h); throws accelcal::Error when it has
  // none, or when the scenario or the options are not valid.
  FixtureSimSource(sim::Scenario scenario, const SimOptions& options, double dead_after_s = 2.0,
                   double gap_factor = 3.0);
  ~FixtureSimSource() override;

  std::string Describe() const override;
  const Fixture& fixture() const override { return declared_; }
  ReadResult Read(double timeout_s, SensorSetSamples* out) override;
  const SourceStatus& status(std::size_t sensor) const override;
  BenchControl* bench() override { return plate_->bench(); }

  // The truth: board i's sensor model, and its mounting as really put in (sensor -> plate, the
  // loose tilt of the current placement included).
  const SensorModel& truth(std::size_t board) const;
  Eigen::Matrix3d mounted_to_plate(std::size_t board) const;
  // The plate's simulator (its scenario, its mounting).
  const SimSource& plate() const { return *plate_; }

 private:
  struct Board;
  void OnPlateForce(double t_s, const Eigen::Matrix3d& f_plate_per_axis_mps2);
  void SettleLooseBoards(double t_s);
  Eigen::Matrix3d BoardForce(const Board& board, double t_s,
                             const Eigen::Matrix3d& f_plate_per_axis_mps2) const;

  sim::BenchFixture bench_fixture_;
  Fixture declared_;
  std::unique_ptr<SimSource> plate_;
  std::vector<std::unique_ptr<Board>> boards_;
  long placements_seen_ = -1;
  double last_placement_s_ = 0.0;
  std::vector<Sample> plate_samples_;  // the plate's own readings, not delivered
};

}  // namespace accelcal

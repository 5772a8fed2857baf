// The fixture tests' bench (fixture_capture_test.cpp, fixture_driver_test.cpp): the simulated
// plate flat out, a procedure of one pose and one turntable run, a plate of 4 with two faults.
#pragma once

#include <memory>

#include "accelcal/acquire/sim/bench_fixture.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/source/fixture_sim_source.h"
#include "accelcal/session/procedure.h"

namespace accelcal::fixture_test {

inline SimOptions Fast() {
  SimOptions o;
  o.speed = 0.0;
  o.bump_probability = 0.0;
  o.settle_s = 0.5;
  return o;
}

inline Procedure OnePoseAndATurntable() {
  Procedure p;
  p.title = "fixture test";
  p.nominal.bias_counts = Eigen::Vector3d::Constant(2048.0);
  p.nominal.scale_counts_per_mps2 = Eigen::Vector3d::Constant(34.8);
  ProcedureStep pose;
  pose.id = "pose_px";
  pose.kind = StepKind::kStatic;
  pose.title = "x up";
  pose.pose_name = "+x";
  pose.up = Eigen::Vector3d::UnitX();
  p.steps.push_back(pose);
  ProcedureStep table;
  table.id = "table_10";
  table.kind = StepKind::kTurntable;
  table.title = "r = 0.10 m";
  table.radius_m = 0.10;
  table.rpm = 120.0;
  table.radial_axis = SensorAxis::kPlusX;
  table.up_axis = SensorAxis::kPlusZ;
  p.steps.push_back(table);
  return p;
}

// A plate of 4 in a row (board 2 at the reference point), board 1 loose, board 4 dead.
inline std::unique_ptr<SensorSetSource> Plate() {
  sim::BenchFixture plate = sim::RowOfBoards(4);
  plate.boards[0].fault = sim::BoardFault::kLoose;
  plate.boards[0].loose_deg = 4.0;
  plate.boards[3].fault = sim::BoardFault::kDead;
  sim::Scenario s = sim::DefaultScenario();
  s.fixture = plate;
  return std::make_unique<FixtureSimSource>(s, Fast(), 0.2);
}

}  // namespace accelcal::fixture_test

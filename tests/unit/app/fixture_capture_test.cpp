// The wizard on a fixture (app/fixture/fixture_capture.h): the lead chosen (square, live,
// nearest the reference), and a lead's accepted capture turned into every sensor's capture of
// the same moments, each judged on its own: a dead board and a board still rocking left out,
// named with why, the others recorded in one transaction with their own turntable radius.
#include "accelcal/app/fixture/fixture_capture.h"

#include <cmath>

#include <fmt/core.h>
#include <gtest/gtest.h>

#include "accelcal/acquire/sim/bench_fixture.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/acquire/source/fixture_sim_source.h"
#include "accelcal/app/fixture/sensor_batch.h"
#include "accelcal/app/wizard/session_clock.h"
#include "accelcal/base/error.h"

namespace accelcal::fixture_capture_test {
namespace {

SimOptions Fast() {
  SimOptions o;
  o.speed = 0.0;
  o.bump_probability = 0.0;
  o.settle_s = 0.5;
  return o;
}

Procedure OnePoseAndATurntable() {
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
std::unique_ptr<SensorSetSource> Plate() {
  sim::BenchFixture plate = sim::RowOfBoards(4);
  plate.boards[0].fault = sim::BoardFault::kLoose;
  plate.boards[0].loose_deg = 4.0;
  plate.boards[3].fault = sim::BoardFault::kDead;
  sim::Scenario s = sim::DefaultScenario();
  s.fixture = plate;
  return std::make_unique<FixtureSimSource>(s, Fast(), 0.2);
}

// What the wizard does for a capture: reads the lead for `seconds` from now and hands over its
// samples as the accepted capture.
Capture LeadCapture(FixtureLeadSource& lead, double seconds, int id, const std::string& label) {
  std::vector<Sample> samples;
  const double until_s = lead.bench()->now_s() + seconds;
  while (samples.empty() || samples.back().t_s < until_s) lead.Read(1.0, &samples);
  Capture c;
  c.id = id;
  c.label = label;
  c.samples = samples;
  return c;
}

TEST(FixtureCapture, TheLeadIsSquareLiveAndNearestTheReference) {
  Fixture f;
  f.sensors.resize(4);
  f.sensors[0].offset_m = Eigen::Vector3d(0.001, 0, 0);
  f.sensors[1].sensor_to_plate = SensorToPlate(SensorAxis::kPlusY, SensorAxis::kMinusX);  // turned
  f.sensors[2].offset_m = Eigen::Vector3d(0.05, 0, 0);
  EXPECT_EQ(ChooseLeadSensor(f, {true, true, true, true}), 3);  // board 4 at the reference
  EXPECT_EQ(ChooseLeadSensor(f, {true, true, true, false}), 0);         // board 4 silent
  EXPECT_EQ(ChooseLeadSensor(f, {false, true, false, false}), -1);      // only a turned one
}

TEST(FixtureCapture, EverySensorsCaptureOfTheLeadsMomentsJudgedOnItsOwn) {
  const Procedure procedure = OnePoseAndATurntable();
  FixtureLeadSource lead(Plate(), 30.0, 1.0);
  ASSERT_EQ(lead.lead(), 1);  // board 2, at the reference point
  std::unique_ptr<SessionJournal> session = MakeMemoryJournal();
  std::vector<std::string> notes;
  FixtureJournal journal(*session, lead, procedure, [&](const std::string& n) { notes.push_back(n); });
  ASSERT_TRUE(session->Sensors().has_value());
  EXPECT_EQ(session->Sensors()->sensors[3].serial, "SIM04");

  // The plate on its +x face: the lead's capture starts as soon as the plate has settled; the
  // loose board still rocks then.
  lead.bench()->PlaceStatic(Eigen::Vector3d::UnitX(), 0.0);
  LeadCapture(lead, 0.6, 0, "settling");  // the plate settles (0.5 s)
  journal.RecordCapture("pose_px", LeadCapture(lead, 3.0, 1, "x up"));
  ASSERT_EQ(session->SensorCaptures(1).size(), 1u);  // the lead
  ASSERT_EQ(session->SensorCaptures(2).size(), 1u);
  EXPECT_TRUE(session->SensorCaptures(0).empty());   // loose: still rocking
  EXPECT_TRUE(session->SensorCaptures(3).empty());   // dead
  EXPECT_EQ(journal.Captures().size(), 1u);          // what the engine sees: the lead's
  const Capture board3 = session->SensorCaptures(2)[0].capture;
  const Capture board2 = session->SensorCaptures(1)[0].capture;
  EXPECT_EQ(board3.samples.front().t_s, board2.samples.front().t_s);  // the same moments
  EXPECT_EQ(board3.samples.size(), board2.samples.size());
  EXPECT_NE(board3.samples.front().raw_counts, board2.samples.front().raw_counts);  // its own
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[0].find("SIM01"), std::string::npos) << notes[0];
  EXPECT_NE(notes[0].find("not still"), std::string::npos) << notes[0];
  EXPECT_NE(notes[1].find("SIM04"), std::string::npos) << notes[1];
  EXPECT_NE(notes[1].find("no samples"), std::string::npos) << notes[1];
  const SessionInputs inputs = session->Inputs();
  EXPECT_EQ(inputs.at(kFixtureStepId).at(kFixtureLeadKey), "SIM02");
  EXPECT_NE(inputs.at(kFixtureStepId).at(SensorLeftOutKey("SIM04", "pose_px")).find("sent nothing"),
            std::string::npos);

  // Long after the placement the loose board rests too: it is taken (in its own tilt).
  LeadCapture(lead, 15.0, 0, "waiting");
  journal.RecordRedoCapture("pose_px#2", LeadCapture(lead, 3.0, 2, "x up"), "pose_px");
  ASSERT_EQ(session->SensorCaptures(0).size(), 1u);
  EXPECT_EQ(CurrentCaptures(session->SensorCaptures(1)).size(), 1u);  // the redo superseded it

  // On the turntable each board has its own radius: 0.10 m +- its offset along the radial x.
  lead.bench()->PlaceTurntable(0.10, 120.0, SensorAxis::kPlusX, SensorAxis::kPlusZ);
  LeadCapture(lead, 1.0, 0, "spinning up");
  Capture run = LeadCapture(lead, 3.0, 3, "r = 0.10 m");
  run.kind = CaptureKind::kTurntable;
  run.radius_m = 0.10;
  run.rpm = 120.0;
  run.up_axis = SensorAxis::kPlusZ;
  journal.RecordCapture("table_10", run);
  EXPECT_NEAR(session->SensorCaptures(1).back().capture.radius_m, 0.10, 1e-12);
  EXPECT_NEAR(session->SensorCaptures(2).back().capture.radius_m, 0.13, 1e-12);
  EXPECT_NEAR(session->SensorCaptures(0).back().capture.radius_m, 0.07, 1e-12);
}


// A resumed run: the wizard puts the lead's samples on the session clock (a constant added to
// the source's t, recorded as the clock's "resume 1"), and a turntable run's accepted samples
// have the table's swing taken out (their readings are not the source's). The others' samples
// of the same moments are found by the clock's shift all the same.
TEST(FixtureCapture, AResumedRunsTurntableCaptureOnTheSessionClock) {
  const Procedure procedure = OnePoseAndATurntable();
  FixtureLeadSource lead(Plate(), 30.0, 1.0);
  std::unique_ptr<SessionJournal> session = MakeMemoryJournal();
  FixtureJournal journal(*session, lead, procedure);
  lead.bench()->PlaceTurntable(0.10, 120.0, SensorAxis::kPlusX, SensorAxis::kPlusZ);
  Capture first = LeadCapture(lead, 1.0, 0, "spinning up");
  ASSERT_TRUE(std::isfinite(lead.first_delivered_t_s()));
  EXPECT_DOUBLE_EQ(lead.first_delivered_t_s(), first.samples.front().t_s);

  const double offset_s = 1234.5;  // the session clock's shift of this run
  journal.RecordInput(SessionClock::kClockStep, "resume 1",
                      fmt::format("t 1200.000000 s -> {:.6f} s, a gap of 34.500 s on the computer's clock",
                                  lead.first_delivered_t_s() + offset_s));
  Capture run = LeadCapture(lead, 3.0, 3, "r = 0.10 m");
  const double source_t0_s = run.samples.front().t_s;
  for (Sample& s : run.samples) {
    s.t_s += offset_s;
    s.raw_counts += Eigen::Vector3d(0.37, -0.21, 0.05);  // a swing taken out
  }
  run.kind = CaptureKind::kTurntable;
  run.radius_m = 0.10;
  run.rpm = 120.0;
  run.up_axis = SensorAxis::kPlusZ;
  journal.RecordCapture("table_10", run);
  ASSERT_EQ(session->SensorCaptures(2).size(), 1u) << "board 3 lacks the run";
  const Capture board3 = session->SensorCaptures(2)[0].capture;
  EXPECT_NEAR(board3.samples.front().t_s, source_t0_s + offset_s, 1e-9);  // on the session clock
  EXPECT_EQ(board3.samples.size(), run.samples.size());
  EXPECT_EQ(session->SensorCaptures(1).size(), 1u);  // the lead's own
}

}  // namespace
}  // namespace accelcal::fixture_capture_test

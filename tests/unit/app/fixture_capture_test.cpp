// The wizard on a fixture (app/fixture/fixture_capture.h): the lead chosen (square, live,
// nearest the reference), and a lead's accepted capture turned into every sensor's capture of
// the same moments, each judged on its own: a dead board and a board still rocking left out,
// named with why, the others recorded in one transaction with their own turntable radius.
#include "accelcal/app/fixture/fixture_capture.h"

#include <cmath>

#include <fmt/core.h>
#include <gtest/gtest.h>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/app/fixture/sensor_batch.h"
#include "accelcal/app/wizard/session_clock.h"
#include "accelcal/base/error.h"
#include "accelcal/session/sensor_journal_view.h"
#include "fixture_test_support.h"

namespace accelcal::fixture_capture_test {
namespace {

using fixture_test::OnePoseAndATurntable;
using fixture_test::Plate;

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

// The turntable radius is measured to the lead: a fixture without a square board at its
// reference point cannot run turntable steps (the others' radii would be off by the lead's
// offset), and is told so with the remedy; static poses alone need none.
TEST(FixtureCapture, TurntableStepsNeedASquareBoardAtTheReferencePoint) {
  Fixture f;
  f.sensors.resize(2);
  f.sensors[0].serial = "B1";
  f.sensors[0].offset_m = Eigen::Vector3d(0.02, 0.03, 0.0);
  f.sensors[1].serial = "B2";
  f.sensors[1].offset_m = Eigen::Vector3d(0.0, 0.0, 0.0);
  const Procedure with_table = OnePoseAndATurntable();
  EXPECT_EQ(FixtureTurntableProblem(f, with_table), "");
  f.sensors[1].offset_m = Eigen::Vector3d(0.06, 0.0, 0.0);
  const std::string why = FixtureTurntableProblem(f, with_table);
  EXPECT_NE(why.find("no board sits at the plate's reference point"), std::string::npos) << why;
  EXPECT_NE(why.find("The nearest, B1, is 36 mm from it"), std::string::npos) << why;
  EXPECT_NE(why.find("subtract its offset [0.02, 0.03, 0]"), std::string::npos) << why;
  Procedure statics = with_table;
  statics.steps.pop_back();  // the turntable step
  EXPECT_EQ(FixtureTurntableProblem(f, statics), "");
  f.sensors[0].offset_m.setZero();
  f.sensors[0].sensor_to_plate = SensorToPlate(SensorAxis::kPlusY, SensorAxis::kMinusX);  // turned
  f.sensors[1].sensor_to_plate = SensorToPlate(SensorAxis::kPlusY, SensorAxis::kMinusX);
  EXPECT_NE(FixtureTurntableProblem(f, with_table).find("no board sits square"), std::string::npos);
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
  // A line per sensor, in order: left out with why, or taken still and in its pose.
  ASSERT_EQ(notes.size(), 4u);
  EXPECT_EQ(notes[0].rfind("sensor 1 (SIM01): left out of 'x up': not still", 0), 0u) << notes[0];
  EXPECT_EQ(notes[1].rfind("sensor 2 (SIM02): taken, still +x;", 0), 0u) << notes[1];
  EXPECT_NE(notes[1].find("(the lead)"), std::string::npos) << notes[1];
  EXPECT_EQ(notes[2].rfind("sensor 3 (SIM03): taken, still +x;", 0), 0u) << notes[2];
  EXPECT_EQ(notes[3].rfind("sensor 4 (SIM04): left out of 'x up': no samples", 0), 0u) << notes[3];
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

// A record step is the lead's; each chunk of it is followed by every other sensor's samples of
// the same moments, on the record's clock (a resumed record's is shifted from the source's), as
// that sensor's own record. A dead board has none; the engine sees the lead's record only.
TEST(FixtureCapture, EachSensorsRecordBesideTheLeads) {
  const Procedure procedure = OnePoseAndATurntable();
  FixtureLeadSource lead(Plate(), 30.0, 1.0);
  std::unique_ptr<SessionJournal> session = MakeMemoryJournal();
  FixtureJournal journal(*session, lead, procedure);
  lead.bench()->PlaceStatic(Eigen::Vector3d::UnitZ(), 0.0);
  const double record_shift_s = 5000.0;
  for (long k = 0; k < 2; ++k) {
    RecordChunk chunk;
    chunk.index = k;
    chunk.samples = LeadCapture(lead, 2.0, 0, "record").samples;
    for (Sample& s : chunk.samples) s.t_s += record_shift_s;
    journal.AppendRecordChunk("noise", chunk);
  }
  const RecordSummary lead_record = session->RecordSummaryOf("noise");
  ASSERT_EQ(lead_record.num_chunks, 2);
  for (const char* serial : {"SIM01", "SIM03"}) {
    const RecordSummary r = session->RecordSummaryOf(SensorRecordStep("noise", serial));
    EXPECT_EQ(r.num_chunks, 2) << serial;
    // One plate, one clock: the same moments, but for the last one or two, which this sensor's
    // link had not delivered yet when the lead's chunk closed (its next chunk takes them).
    EXPECT_GE(r.num_samples, lead_record.num_samples - 2) << serial;
    EXPECT_LE(r.num_samples, lead_record.num_samples) << serial;
    EXPECT_DOUBLE_EQ(r.t_first_s, lead_record.t_first_s) << serial;
    EXPECT_NEAR(r.t_last_s, lead_record.t_last_s, 0.025) << serial;
  }
  EXPECT_EQ(session->RecordSummaryOf(SensorRecordStep("noise", "SIM04")).num_chunks, 0);  // dead
  EXPECT_EQ(journal.RecordSteps(), std::vector<std::string>{"noise"});
  // Board 3's own readings, through its view.
  std::vector<Sample> board3;
  SensorJournalView(*session, 2).VisitRecordChunks("noise", [&](const RecordChunk& c) {
    board3.insert(board3.end(), c.samples.begin(), c.samples.end());
  });
  std::vector<Sample> board2;
  SensorJournalView(*session, 1).VisitRecordChunks("noise", [&](const RecordChunk& c) {
    board2.insert(board2.end(), c.samples.begin(), c.samples.end());
  });
  ASSERT_GE(board3.size() + 2, board2.size());
  ASSERT_FALSE(board3.empty());
  EXPECT_EQ(board3.front().t_s, board2.front().t_s);
  EXPECT_NE(board3.front().raw_counts, board2.front().raw_counts);
}

// What each sensor keeps behind the newest sample: the longest capture and a margin; a record
// step (12 hours of drift) is the lead's alone and keeps nothing of the others.
TEST(FixtureCapture, KeptForTheLongestCaptureNotForARecord) {
  Procedure p = OnePoseAndATurntable();
  p.steps[0].duration_s = 10.0;
  p.steps[1].duration_s = 20.0;
  EXPECT_DOUBLE_EQ(FixtureKeepS(p), 35.0);
  ProcedureStep drift;
  drift.id = "drift";
  drift.kind = StepKind::kRecord;
  drift.duration_s = 43200.0;
  p.steps.push_back(drift);
  EXPECT_DOUBLE_EQ(FixtureKeepS(p), 35.0);
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

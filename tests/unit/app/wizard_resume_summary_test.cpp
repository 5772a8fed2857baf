// The resume summary (issue 15): the steps a resumed session holds, in the procedure's order and
// by their titles, never internal ids sorted alphabetically ("done: pose_mx (skipped) ...
// welcome (ok)" before).
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/source/sim_source.h"
#include "accelcal/app/wizard/resume_summary.h"
#include "accelcal/app/wizard/wizard_engine.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/session/sensor_journal_view.h"
#include "accelcal/session/session_journal.h"

namespace accelcal::wizard_resume_summary_test {
namespace {

Procedure FullProcedure() {
  return LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml");
}

// A still capture of `up` (platform frame) through the seed's nominal model.
Capture StillCapture(int id, const std::string& label, const Eigen::Vector3d& up, double t0_s) {
  Capture c;
  c.id = id;
  c.label = label;
  for (int k = 0; k < 50; ++k) {
    Sample s;
    s.t_s = t0_s + k * 0.01;
    s.raw_counts = Eigen::Vector3d::Constant(2048.0) + 34.8 * 9.80665 * up +
                   Eigen::Vector3d(k % 2, (k / 2) % 2, (k / 3) % 2);
    c.samples.push_back(s);
  }
  return c;
}

// A session of several sensors records its lead and its plate's placement before the engine
// starts: its first run is no resume (it said "Resuming session ...: 0 captures" before).
TEST(WizardResumeSummaryTest, ASetsOwnInputsAreNoResume) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  journal->RecordInput(kSensorSetStep, kSensorSetLeadKey, "SIM02");
  journal->RecordInput(kSensorSetStep, kSensorSetPlacementKey, "0.1");
  SimOptions sim_options;
  sim_options.speed = 0.0;
  SimSource sim(sim::DefaultScenario(), sim_options);
  WizardEngine engine(FullProcedure(), sim, *journal, WizardOptions{"test", "op", "SN1", {}, 2.0, {}});
  for (const std::string& line : engine.View().lines)
    EXPECT_EQ(line.find("Resuming session"), std::string::npos) << line;
  // An answer of a run is a resume.
  journal->RecordInput("welcome", "device", "SN1");
  WizardEngine again(FullProcedure(), sim, *journal, WizardOptions{"test", "op", "SN1", {}, 2.0, {}});
  ASSERT_FALSE(again.View().lines.empty());
  EXPECT_EQ(again.View().lines[0], "Resuming session test: 0 captures and 0 steps already recorded.");
}

TEST(WizardResumeSummaryTest, ListsTheStepsInTheProceduresOrderByTitle) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  journal->RecordStepDone("welcome", "ok");
  journal->RecordStepDone("level", "level: tilt 0.10 deg about x, 0.05 deg about y");
  // Recorded out of the procedure's order: +x up first (after a b), then +z up.
  journal->RecordCapture("pose_px", StillCapture(2, "+x up", Eigen::Vector3d::UnitX(), 10.0));
  journal->RecordCapture("pose_pz", StillCapture(1, "+z up", Eigen::Vector3d::UnitZ(), 20.0));
  journal->RecordStepDone("pose_mz", "skipped");
  journal->RecordStepDone("tt_x_100", "skipped");
  SimOptions sim_options;
  sim_options.speed = 0.0;
  SimSource sim(sim::DefaultScenario(), sim_options);
  WizardEngine engine(FullProcedure(), sim, *journal, WizardOptions{"test", "op", "SN1", {}, 2.0, {}});
  const std::vector<std::string> lines = engine.View().lines;
  ASSERT_GE(lines.size(), 7u);
  EXPECT_EQ(lines[0], "Resuming session test: 2 captures and 4 steps already recorded.");
  EXPECT_EQ(lines[1], "  Welcome: done");
  EXPECT_EQ(lines[2], "  Level the table: done");
  EXPECT_EQ(lines[3], "  +z up: done (capture 1)");
  EXPECT_EQ(lines[4], "  -z up: skipped");
  EXPECT_EQ(lines[5], "  +x up: done (capture 2)");
  EXPECT_EQ(lines[6], "  +x radial, +z up at 100 mm, 120 rpm: skipped");
  for (const std::string& line : lines) {
    EXPECT_EQ(line.find("pose_"), std::string::npos) << line;
    EXPECT_EQ(line.find("tt_x"), std::string::npos) << line;
  }
}

TEST(WizardResumeSummaryTest, NamesASupersededCaptureBesideItsRedo) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  journal->RecordStepDone("welcome", "ok");
  journal->RecordCapture("pose_pz", StillCapture(1, "+z up", Eigen::Vector3d::UnitZ(), 10.0));
  journal->RecordRedoCapture("pose_pz#2", StillCapture(2, "+z up", Eigen::Vector3d::UnitZ(), 20.0), "pose_pz");
  SessionModel model(*journal);
  const std::vector<std::string> lines = ResumeSummaryLines(FullProcedure(), model, "welcome");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1], "  +z up: done (capture 2; capture 1 taken again, superseded)");
}

// Issue 27, item 8: the three runs of a mounting looked alike ("Take '+y radial, +z up' again?"
// three times); the radius and the speed tell them apart.
TEST(WizardResumeSummaryTest, ATurntableTitleNamesItsRadiusAndSpeed) {
  ProcedureStep s;
  s.kind = StepKind::kTurntable;
  s.pose_name = "y radial, z up";
  s.title = s.pose_name;
  s.radius_m = 0.15;
  s.rpm = 120;
  EXPECT_EQ(StepDisplayTitle(s), "y radial, z up at 150 mm, 120 rpm");
  s.title = "Outer run";  // a title of its own is kept
  EXPECT_EQ(StepDisplayTitle(s), "Outer run");
}

}  // namespace
}  // namespace accelcal::wizard_resume_summary_test

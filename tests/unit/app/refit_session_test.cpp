// `accelcal refit`'s use case (issue 27, item 5): a finished session fitted again with a
// corrected gravity; the earlier result kept, the change recorded, a refused value refused
// before anything is recorded; and the flags a resumed wizard does not use, named.
#include <string>

#include <gtest/gtest.h>

#include "accelcal/app/refit_session.h"
#include "accelcal/app/wizard/refit_answer.h"
#include "accelcal/base/error.h"
#include "accelcal/io/scenario_file.h"
#include "test_support.h"
#include "wizard_test_support.h"

namespace accelcal {
namespace {

using testing::Contains;

// A lab at the equator that took the standard gravity: the session ends FAIL.
std::shared_ptr<SessionJournal> FinishedOnTheStandardGravity() {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  testing::WizardRig rig(testing::ShortFullProcedure(),
                         sim::LoadScenario(std::string(ACCELCAL_SOURCE_DIR) + "/scenarios/clumsy_local_gravity.toml"),
                         journal);
  testing::AcceptUntil(rig.engine, testing::Never);
  EXPECT_EQ(rig.engine.View().verdict, "FAIL");
  return journal;
}

RefitRequest BaseRefitRequest() {
  RefitRequest r;
  r.session_name = "s.db";
  r.source = "sim";
  r.now_utc = "2026-11-27T10:00:00Z";
  return r;
}

TEST(RefitSession, ACorrectedGravityIsFittedAgainAndTheEarlierResultKept) {
  const std::shared_ptr<SessionJournal> journal = FinishedOnTheStandardGravity();
  EXPECT_EQ(journal->ResultCount(), 1);
  const std::string first = *journal->Result();
  RefitRequest r = BaseRefitRequest();
  r.gravity = GravitySpec::Given(9.7803, 1e-5);
  const RefitOutcome out = RefitSession(*journal, testing::ShortFullProcedure(), r);
  EXPECT_EQ(out.refit_step, "refit 1");
  EXPECT_EQ(out.changes, std::vector<std::string>{"gravity: standard -> 9.7803 +- 1e-05"});
  EXPECT_EQ(out.earlier_results, 1);
  EXPECT_EQ(out.summary.verdict, Verdict::kPass);
  EXPECT_EQ(journal->ResultCount(), 2);
  EXPECT_NE(*journal->Result(), first);
  const auto inputs = journal->Inputs();
  EXPECT_EQ(inputs.at("welcome").at("gravity"), "9.7803 +- 1e-05");
  EXPECT_EQ(inputs.at("refit 1").at("change 1"), "gravity: standard -> 9.7803 +- 1e-05");
  EXPECT_EQ(journal->DoneSteps().at("refit 1"), "recorded");
  const std::vector<std::string> history = SessionHistory(*journal, journal->ResultCount() - 1);
  ASSERT_EQ(history.size(), 2u);
  EXPECT_EQ(history[0], "refit 1 (2026-11-27T10:00:00Z): gravity: standard -> 9.7803 +- 1e-05");
  EXPECT_EQ(history[1], "1 earlier calibration is kept in the session; this is the latest");
  // A wizard run on the session with a gravity flag: named, not silently ignored.
  const std::vector<std::string> notes = UnusedResumeFlags(*journal, "s.db", "--latitude 0", "");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_TRUE(Contains(notes[0], "--latitude 0 ignored: this session's gravity was recorded at its welcome "
                                 "(9.7803 +- 1e-05); to calibrate it with another: accelcal refit s.db --latitude 0"))
      << notes[0];
  EXPECT_TRUE(UnusedResumeFlags(*MakeMemoryJournal(), "new.db", "--latitude 0", "Lab 2").empty());
}

// A session resumed before its end: the flag is named, and the refit is for when it is finished
// (a session without a calibration has nothing to refit).
TEST(RefitSession, AFlagOnASessionUnderWayIsNamedWithTheRefitForItsEnd) {
  const std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  journal->RecordInput("welcome", "gravity", "standard");
  journal->RecordInput("welcome", "place", "Lab 1");
  const std::vector<std::string> notes = UnusedResumeFlags(*journal, "s.db", "--latitude 0", "Lab 2");
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[0], "--latitude 0 ignored: this session's gravity was recorded at its welcome (standard); to "
                      "calibrate it with another, once the session is finished: accelcal refit s.db --latitude 0");
  EXPECT_EQ(notes[1], "--place Lab 2 ignored: this session's place was recorded at its welcome (Lab 1); to "
                      "change it, once the session is finished: accelcal refit s.db --place 'Lab 2'");
}

TEST(RefitSession, ARefusedValueRecordsNothing) {
  const std::shared_ptr<SessionJournal> journal = FinishedOnTheStandardGravity();
  const auto inputs = journal->Inputs();
  RefitRequest r = BaseRefitRequest();
  r.equipment_answer = "hammer id 3";
  EXPECT_THROW(RefitSession(*journal, testing::ShortFullProcedure(), r), Error);
  r = BaseRefitRequest();
  r.device = "";  // the seed procedure requires the serial
  EXPECT_THROW(RefitSession(*journal, testing::ShortFullProcedure(), r), Error);
  EXPECT_EQ(journal->ResultCount(), 1);
  EXPECT_EQ(journal->Inputs(), inputs);
  // Nothing to refit in a session without a calibration.
  EXPECT_THROW(RefitSession(*MakeMemoryJournal(), testing::ShortFullProcedure(), BaseRefitRequest()), Error);
}

// The wizard opened again on the finished session offers the refit ("refit with new inputs?"):
// a wrong answer is refused with what to type; the corrected gravity refits it (the earlier
// result kept) and the ending says the new verdict.
TEST(RefitSession, TheWizardOnAFinishedSessionOffersTheRefit) {
  const std::shared_ptr<SessionJournal> journal = FinishedOnTheStandardGravity();
  testing::WizardRig again(testing::ShortFullProcedure(),
                           sim::LoadScenario(std::string(ACCELCAL_SOURCE_DIR) + "/scenarios/clumsy_local_gravity.toml"),
                           journal);
  WizardView v = again.engine.View();
  ASSERT_TRUE(v.input.has_value());
  EXPECT_EQ(v.input->key, "refit");
  EXPECT_FALSE(v.finished);
  EXPECT_EQ(v.verdict, "FAIL");
  EXPECT_TRUE(Contains(v.prompt, "Refit it with new inputs?")) << v.prompt;
  again.engine.Handle({IntentKind::kSubmitText, "latitude 0"});
  v = again.engine.View();
  ASSERT_TRUE(v.input.has_value());
  EXPECT_TRUE(Contains(v.input->error, "start each correction with what it corrects")) << v.input->error;
  EXPECT_EQ(journal->ResultCount(), 1);
  again.engine.Handle({IntentKind::kSubmitText, "gravity 9.7803 +- 0.00001"});
  v = again.engine.View();
  EXPECT_TRUE(v.finished);
  EXPECT_TRUE(again.engine.completed());
  EXPECT_EQ(v.verdict, "PASS");
  EXPECT_EQ(v.prompt, "Calibration complete.");
  EXPECT_TRUE(testing::AnyContains(v.lines, "gravity: standard -> 9.7803 +- 1e-05"));
  EXPECT_TRUE(testing::AnyContains(v.lines, "The earlier calibration is kept in the session"));
  EXPECT_EQ(journal->ResultCount(), 2);
  EXPECT_EQ(journal->Inputs().at("welcome").at("gravity"), "9.7803 +- 1e-05");
}

TEST(RefitAnswer, EachCorrectionStartsWithWhatItCorrects) {
  const RefitAnswer a = ParseRefitAnswer(
      "gravity lat -34.9 alt 43; equipment ruler id RUL-07 cal C-2291; turntable cal T-118; device SN-42; "
      "operator Ana Paz; place Lab 2, bench 3");
  ASSERT_TRUE(a.ok()) << a.error;
  ASSERT_TRUE(a.request.gravity.has_value());
  EXPECT_NEAR(a.request.gravity->gravity_mps2, 9.797, 0.002);  // WGS84 at -34.9 deg, 43 m
  EXPECT_EQ(a.request.equipment_answer, "ruler id RUL-07 cal C-2291; turntable cal T-118");
  EXPECT_EQ(a.request.device, "SN-42");
  EXPECT_EQ(a.request.operator_name, "Ana Paz");
  EXPECT_EQ(a.request.place, "Lab 2, bench 3");
  EXPECT_FALSE(ParseRefitAnswer("gravity sometimes").ok());
  EXPECT_FALSE(ParseRefitAnswer("turntable cal T-118").ok());  // equipment must be said first
  EXPECT_FALSE(ParseRefitAnswer(" ; ").ok());
}

}  // namespace
}  // namespace accelcal

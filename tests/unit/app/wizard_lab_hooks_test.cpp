// The wizard's welcome and the lab's equipment register (WizardOptions::check_equipment, which
// `accelcal wizard` points at app/lab_equipment_check.h's WelcomeEquipmentCheck on a bench
// pointed at a lab): the procedure's items checked when the welcome opens, the items the
// equipment answer names checked again, the warnings shown at the welcome and the last ones
// carried to the screen after it. A stand-in for the lab here; tests/lab/ and
// e2e_two_benches.sh run the real check against a real server.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "wizard_test_support.h"

namespace accelcal {
namespace {

using testing::AnyContains;
using testing::FullProcedure;
using testing::WizardRig;

// A lab whose register holds the turntable TT-01 expired and the ruler RUL-02 in date, and knows
// nothing else; every call's ids are kept. `unreachable` non-empty: a lab out of reach.
struct StandInLab {
  std::vector<std::vector<std::string>> asked;
  std::string unreachable;
  WelcomeLabCheck Check(const std::vector<EquipmentItem>& items) {
    std::vector<std::string> ids, warnings;
    for (const EquipmentItem& item : items) {
      ids.push_back(item.identification);
      if (item.identification == "TT-01") warnings.push_back("turntable TT-01: its calibration expired");
      else if (item.identification != "RUL-02") warnings.push_back(item.identification + ": not in the register");
    }
    asked.push_back(ids);
    if (!unreachable.empty()) return {{}, unreachable};
    return {warnings, ""};
  }
};

WizardOptions WithLab(StandInLab& lab) {
  WizardOptions o{"test", "op", "SN1", {}, 2.0, {}};
  o.check_equipment = [&lab](const std::vector<EquipmentItem>& items) { return lab.Check(items); };
  return o;
}

// A bench whose lab offers no equipment answer: the procedure's items (its example ids), as a
// real bench's welcome has them. The virtual bench's lab offers its own (sim::LabSpec).
sim::Scenario BenchWithTheProceduresItems() {
  sim::Scenario scenario = sim::DefaultScenario();
  scenario.lab.equipment = "keep";
  return scenario;
}

void AnswerUpToEquipment(WizardEngine& e) {
  for (int i = 0; i < 4; ++i) e.Handle({IntentKind::kAccept, ""});
  ASSERT_TRUE(e.View().input.has_value());
  ASSERT_EQ(e.View().input->key, "equipment");
}

TEST(WizardLabHooks, TheWelcomeShowsWhatTheLabSaysOfTheProceduresEquipment) {
  StandInLab lab;
  WizardRig rig(FullProcedure(), BenchWithTheProceduresItems(), nullptr, WithLab(lab));
  ASSERT_EQ(lab.asked.size(), 1u);
  EXPECT_EQ(lab.asked[0],
            (std::vector<std::string>{"RUL-01 (example)", "TT-01 (example)", "LVL-01 (example)", "PR-01 (example)"}));
  const WizardView first = rig.engine.View();
  EXPECT_EQ(first.input->key, "device");
  EXPECT_TRUE(AnyContains(first.lines, "The lab's equipment register warns")) << ::testing::PrintToString(first.lines);
  EXPECT_TRUE(AnyContains(first.lines, "TT-01 (example): not in the register"));
  // Shown on every question of the welcome, up to the equipment's, where other items are named.
  AnswerUpToEquipment(rig.engine);
  EXPECT_TRUE(AnyContains(rig.engine.View().lines, "RUL-01 (example): not in the register"));

  // The answer names other items: checked again, as edited.
  rig.engine.Handle({IntentKind::kSubmitText, "turntable id TT-01; ruler id RUL-02"});
  // The procedure issues a certificate: an answer that leaves example ids is refused once, before
  // the lab is asked; the same answer again goes on.
  ASSERT_EQ(lab.asked.size(), 1u);
  ASSERT_TRUE(rig.engine.View().input.has_value());
  EXPECT_NE(rig.engine.View().input->error.find("not your bench's own"), std::string::npos);
  rig.engine.Handle({IntentKind::kSubmitText, "turntable id TT-01; ruler id RUL-02"});
  ASSERT_EQ(lab.asked.size(), 2u);
  EXPECT_EQ(lab.asked[1], (std::vector<std::string>{"RUL-02", "TT-01", "LVL-01 (example)", "PR-01 (example)"}));
  // The welcome is over; what the lab still warns of is on the next screen, until a key.
  const WizardView next = rig.engine.View();
  EXPECT_EQ(next.step_title, "Level the table");
  EXPECT_EQ(next.notice,
            "Equipment: turntable TT-01: its calibration expired; LVL-01 (example): not in the register; "
            "PR-01 (example): not in the register");
  rig.engine.Handle({IntentKind::kAccept, ""});
  EXPECT_EQ(rig.engine.View().notice, "");
}

TEST(WizardLabHooks, ValidEquipmentLeavesTheWelcomeAsItWas) {
  StandInLab lab;
  Procedure procedure = FullProcedure();
  for (EquipmentItem& item : procedure.equipment) item.identification = "RUL-02";
  WizardRig rig(procedure, BenchWithTheProceduresItems(), nullptr, WithLab(lab));
  EXPECT_FALSE(AnyContains(rig.engine.View().lines, "equipment register"));
  AnswerUpToEquipment(rig.engine);
  rig.engine.Handle({IntentKind::kAccept, ""});
  EXPECT_EQ(lab.asked.size(), 2u);
  EXPECT_EQ(rig.engine.View().notice, "");
}

// The virtual bench's lab offers its own identified items at the equipment question: the lab
// checks those when the welcome opens (Enter keeps them), not the procedure's example ids.
TEST(WizardLabHooks, TheItemsTheEquipmentQuestionOffersAreTheOnesChecked) {
  StandInLab lab;
  WizardRig rig(FullProcedure(), sim::DefaultScenario(), nullptr, WithLab(lab));
  ASSERT_EQ(lab.asked.size(), 1u);
  EXPECT_EQ(lab.asked[0], (std::vector<std::string>{"SIM-RUL-01", "SIM-TT-01", "SIM-LVL-01", "SIM-PR-01"}));
  EXPECT_FALSE(AnyContains(rig.engine.View().lines, "(example)")) << ::testing::PrintToString(rig.engine.View().lines);
  AnswerUpToEquipment(rig.engine);
  rig.engine.Handle({IntentKind::kAccept, ""});
  ASSERT_EQ(lab.asked.size(), 2u);
  EXPECT_EQ(lab.asked[1], lab.asked[0]);
}

// A lab out of reach: every question of the welcome says so in plain words (nothing checked, the
// session goes on and is kept on the bench to publish later), with libpq's reason; the welcome
// goes on as without a lab and leaves nothing on the next screen.
TEST(WizardLabHooks, ALabOutOfReachIsSaidAtTheWelcomeAndTheSessionGoesOn) {
  StandInLab lab;
  lab.unreachable = "cannot reach the lab store (database lab on 10.1.2.3:5432 as bench_3): timeout expired";
  WizardRig rig(FullProcedure(), sim::DefaultScenario(), nullptr, WithLab(lab));
  const auto says_it = [](const WizardView& v) {
    EXPECT_TRUE(AnyContains(v.lines, "The lab's register cannot be reached, so the equipment's calibration "
                                     "dates are not checked"))
        << ::testing::PrintToString(v.lines);
    EXPECT_TRUE(AnyContains(v.lines, "The session goes on here and is kept on this bench"));
    EXPECT_TRUE(AnyContains(v.lines, "it waits for `accelcal lab publish`"));
    EXPECT_TRUE(AnyContains(v.lines, "10.1.2.3:5432 as bench_3): timeout expired"));
    EXPECT_FALSE(AnyContains(v.lines, "equipment register warns"));
  };
  says_it(rig.engine.View());
  AnswerUpToEquipment(rig.engine);
  says_it(rig.engine.View());
  rig.engine.Handle({IntentKind::kAccept, ""});
  const WizardView next = rig.engine.View();
  EXPECT_EQ(next.step_title, "Level the table");
  EXPECT_EQ(next.notice, "");
  EXPECT_FALSE(AnyContains(next.lines, "cannot be reached"));
}

TEST(WizardLabHooks, NoCheckWithoutALabNorOnceTheWelcomeIsBehind) {
  WizardRig without(FullProcedure(), sim::DefaultScenario());
  EXPECT_FALSE(AnyContains(without.engine.View().lines, "equipment register"));

  // A session resumed after its welcome is not checked again at construction.
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  {
    WizardRig first(FullProcedure(), sim::DefaultScenario(), journal);
    AnswerUpToEquipment(first.engine);
    first.engine.Handle({IntentKind::kAccept, ""});
    ASSERT_EQ(first.engine.View().step_title, "Level the table");
  }
  StandInLab lab;
  WizardRig resumed(FullProcedure(), sim::DefaultScenario(), journal, WithLab(lab));
  EXPECT_TRUE(lab.asked.empty());
  EXPECT_FALSE(AnyContains(resumed.engine.View().lines, "equipment register"));
}

}  // namespace
}  // namespace accelcal

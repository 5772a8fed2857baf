// The wizard's settling wait (app/wizard/settling_wait.h): a sensor seen still settling after
// its earlier changes of pose is given the time it needs before the next capture, and the screen
// says what it waits for; a sensor that settles at once is never kept waiting.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/app/wizard/settling_wait.h"
#include "accelcal/calibration/settling.h"
#include "physics_captures.h"
#include "wizard_test_support.h"

namespace accelcal {
namespace {

physgen::Effects Settling() {
  physgen::Effects e;
  e.settle_fraction = {0.005, 0.005, 0.005};  // the `settling` case of accelcal_physgen
  return e;
}

// The wait before the last capture of the set, from the ones before it.
SettlingWait WaitBeforeLast(const testing::PhysicsSet& set) {
  std::vector<Capture> before(set.captures.begin(), set.captures.end() - 1);
  return PlanSettlingWait(before, set.captures.back().stats().mean_counts);
}

TEST(SettlingWait, PlannedFromCapturesThatWereStillSettling) {
  for (unsigned long long seed : {1ull, 2ull, 3ull}) {
    // The wait before the first static pose taken again after the whole plan.
    testing::PhysicsSet set = testing::MakePhysicsSet(Settling(), seed);
    const std::vector<Capture>& statics = set.captures;
    const Capture next = statics.front();
    const SettlingWait w = PlanSettlingWait(statics, next.stats().mean_counts);
    std::vector<Capture> judged = statics;
    const SettlingFinding f = HandleSettling(judged);
    EXPECT_GT(w.wait_s, 0.0) << "seed " << seed << ": detected " << f.detected << " tau " << f.tau_s
                             << " share " << f.lag_share.transpose() << " t " << f.t_statistic.transpose();
    EXPECT_LE(w.wait_s, 120.0);
    EXPECT_NE(w.reason.find("still settling after you set it down: the earlier poses were still moving "),
              std::string::npos) << w.reason;
    EXPECT_NE(w.reason.find("counts as their capture began (settling time about "), std::string::npos) << w.reason;
  }
}

TEST(SettlingWait, NoWaitForASensorThatSettlesAtOnce) {
  for (unsigned long long seed = 1; seed <= 4; ++seed)
    EXPECT_EQ(WaitBeforeLast(testing::MakePhysicsSet(physgen::Effects{}, seed)).wait_s, 0.0) << "seed " << seed;
  // Too few captures to tell.
  EXPECT_EQ(PlanSettlingWait({}, Eigen::Vector3d::Zero()).wait_s, 0.0);
}

sim::Scenario SettlingBench() {
  sim::Scenario s = sim::DefaultScenario();
  s.effects.settling_share = Eigen::Vector3d::Constant(0.003);
  s.effects.settling_tau_s = 15.0;
  return s;
}

bool Waiting(const WizardView& v) { return v.prompt.find("s more") != std::string::npos; }

// Issue 29's done-when: a settling sensor on the virtual bench is caught in the wizard. Once the
// captures show it, a capture waits, still and in its pose, before it begins, saying why.
TEST(SettlingWait, TheWizardWaitsForASettlingSensorOnTheVirtualBench) {
  testing::WizardRig rig(testing::FullProcedure(), SettlingBench());
  bool waited = false;
  std::string said;
  for (int i = 0; i < 1000000 && !waited; ++i) {
    const WizardView v = rig.engine.View();
    if (v.finished) break;
    if (Waiting(v)) {
      waited = true;
      said = v.prompt;
      break;
    }
    if (testing::Busy(v))
      rig.engine.Poll(0.0);
    else
      rig.engine.Handle({IntentKind::kAccept, ""});
  }
  if (!waited) {
    std::vector<Capture> judged;
    for (const JournalCapture& c : rig.journal->Captures()) judged.push_back(c.capture);
    const SettlingFinding f = HandleSettling(judged);
    FAIL() << "no capture waited for the sensor to settle: " << judged.size() << " captures, detected " << f.detected
           << " tau " << f.tau_s << " share " << f.lag_share.transpose() << " t " << f.t_statistic.transpose()
           << " critical " << f.critical_score << " largest offset " << f.largest_offset_counts;
  }
  EXPECT_NE(said.find("still settling after you set it down"), std::string::npos) << said;
  EXPECT_NE(said.find("; waiting "), std::string::npos) << said;
  // It waits, then captures, and the session goes on to its end.
  testing::AcceptUntil(rig.engine, testing::Never);
  EXPECT_TRUE(rig.engine.View().finished);
}

TEST(SettlingWait, TheDefaultBenchNeverWaits) {
  testing::WizardRig rig(testing::FullProcedure(), sim::DefaultScenario());
  bool waited = false;
  for (int i = 0; i < 1000000; ++i) {
    const WizardView v = rig.engine.View();
    if (v.finished) break;
    waited = waited || Waiting(v);
    if (testing::Busy(v))
      rig.engine.Poll(0.0);
    else
      rig.engine.Handle({IntentKind::kAccept, ""});
  }
  EXPECT_TRUE(rig.engine.View().finished);
  EXPECT_FALSE(waited);
}

}  // namespace
}  // namespace accelcal

// A source that ends (a recording replayed to its end) while the noise floor is measured: the
// wizard says so, and Enter asks for the noise floor again instead of starting a capture without
// one. (Reproduces a defect: the capture was started with the floor that was never measured, an
// empty optional read, and the wizard stopped on std::bad_alloc or went on with garbage limits.)
#include <unistd.h>

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/acquire/source/source_spec.h"
#include "wizard_test_support.h"

namespace accelcal {
namespace {

std::string ShortRecording() {
  const std::string path = ::testing::TempDir() + "accelcal_" + std::to_string(::getpid()) + "_ends.txt";
  std::ofstream out(path);
  for (int i = 0; i < 20; ++i) out << i * 0.01 << " 2051 2040 2400\n";
  return path;
}

TEST(WizardSourceEnd, WhileTheNoiseFloorIsMeasuredItIsAskedForAgain) {
  const std::unique_ptr<SampleSource> source = OpenSource("file:" + ShortRecording(), {});
  const std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  WizardEngine engine(testing::FullProcedure(), *source, *journal, WizardOptions{"test", "op", "SN1", {}, 2.0, {}});
  // The welcome: four answers, and the equipment's twice (its example ids refused once).
  for (int i = 0; i < 6; ++i) engine.Handle({IntentKind::kAccept, ""});
  ASSERT_EQ(engine.View().prompt.rfind("Noise floor:", 0), 0u) << engine.View().prompt;
  engine.Handle({IntentKind::kAccept, ""});  // measure it
  for (int i = 0; i < 10 && engine.View().problem.empty(); ++i) engine.Poll(0.0);
  EXPECT_EQ(engine.View().problem.rfind("the source has ended", 0), 0u) << engine.View().problem;
  EXPECT_EQ(engine.View().screen, WizardScreen::kError);
  engine.Handle({IntentKind::kAccept, ""});  // try again: the floor first, no capture without it
  const WizardView v = engine.View();
  EXPECT_EQ(v.prompt.rfind("Noise floor:", 0), 0u) << v.prompt;
  EXPECT_EQ(v.screen, WizardScreen::kPlacePose);
  EXPECT_TRUE(v.noise_floor_text.empty());
  EXPECT_TRUE(journal->Captures().empty());
}

}  // namespace
}  // namespace accelcal

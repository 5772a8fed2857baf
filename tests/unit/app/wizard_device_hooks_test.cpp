// Issue 30, the wizard's side of a live device: what the source's device holds said at the
// welcome and recorded; the source's resolution said at the noise floor where it limits it; the
// source's notices on screen in the bench's words (SourceNotices), the figures one key away; the
// write-back step's place in a procedure and what it says on a source that is no vehicle. The
// write into a vehicle itself is proven end to end against the node-mavlink vehicle
// (tests/e2e/vehicle_wizard.sh). The sim at speed 0 behind a source that reports what a device
// would (its resolution, a notice, lost samples).
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/app/wizard/source_notices.h"
#include "accelcal/base/error.h"
#include "accelcal/session/session_inputs.h"
#include "test_support.h"
#include "wizard_test_support.h"

namespace accelcal::wizard_device_hooks_test {
namespace {

using testing::AcceptUntil;
using testing::AnyContains;
using testing::FastSim;
using testing::FullProcedure;
using testing::PollUntilQuestion;

// The sim, reporting what a device would: its resolution, lost samples, and a notice on the next
// read. The bench's controls are the sim's.
class DeviceLikeSource final : public SampleSource {
 public:
  explicit DeviceLikeSource(SampleSource& inner) : inner_(inner) {}
  std::string Describe() const override { return "test device"; }
  ReadResult Read(double timeout_s, std::vector<Sample>* out) override {
    ReadResult r = inner_.Read(timeout_s, out);
    const std::string notice = status_.last_notice;
    const SourceNoticeKind kind = status_.last_notice_kind;
    status_ = inner_.status();
    status_.resolution_counts = resolution_counts;
    status_.lost_frames = lost_frames;
    status_.last_notice = notice;
    status_.last_notice_kind = kind;
    if (!next_notice.empty()) {
      status_.last_notice = next_notice;
      status_.last_notice_kind = next_kind;
      r.notice = true;
      next_notice.clear();
    }
    return r;
  }
  const SourceStatus& status() const override { return status_; }
  BenchControl* bench() override { return inner_.bench(); }

  double resolution_counts = kNaN;
  long lost_frames = 0;
  std::string next_notice;
  SourceNoticeKind next_kind = SourceNoticeKind::kOther;

 private:
  SampleSource& inner_;
  SourceStatus status_;
};

struct DeviceRig {
  explicit DeviceRig(Procedure procedure, WizardOptions options = WizardOptions{"test", "op", "SN1", {}, 2.0, {}},
                     std::shared_ptr<SessionJournal> shared = nullptr)
      : sim(sim::DefaultScenario(), FastSim()), device(sim),
        journal(shared ? std::move(shared) : std::shared_ptr<SessionJournal>(MakeMemoryJournal())),
        engine(std::move(procedure), device, *journal, std::move(options)) {}
  SimSource sim;
  DeviceLikeSource device;
  std::shared_ptr<SessionJournal> journal;
  WizardEngine engine;
};

WizardOptions WithDeviceLines(std::vector<std::string> lines) {
  WizardOptions options{"test", "op", "SN1", {}, 2.0, {}};
  options.device_lines = std::move(lines);
  return options;
}

// The full procedure's static poses, the fit, the report and a write-back after it.
Procedure StaticsThenWriteBack() {
  Procedure p = FullProcedure();
  std::vector<ProcedureStep> steps;
  for (const ProcedureStep& s : p.steps)
    if (s.kind == StepKind::kStatic || s.kind == StepKind::kFit || s.kind == StepKind::kReport) steps.push_back(s);
  ProcedureStep write_back;
  write_back.id = "write_back";
  write_back.kind = *StringToStepKind("write_back");
  write_back.title = "Write the calibration into the vehicle";
  write_back.required = false;
  steps.push_back(write_back);
  p.steps = steps;
  return p;
}

// Answers the welcome and stops at the noise floor's question.
void ToNoiseFloor(WizardEngine& e) {
  AcceptUntil(e, [](const WizardView& v) { return v.prompt.rfind("Noise floor:", 0) == 0; });
}

TEST(WizardDeviceHooks, TheDevicesOwnCalibrationIsShownAtTheWelcomeAndRecorded) {
  WizardOptions options{"test", "op", "SN1", {}, 2.0, {}};
  options.device_lines = {"INS_ACCOFFS: x 0.3, y 0, z 0 m/s^2", "AHRS_ORIENTATION 10 (ROLL_180_YAW_90)"};
  DeviceRig rig(StaticsThenWriteBack(), options);
  const WizardView welcome = rig.engine.View();
  ASSERT_EQ(welcome.screen, WizardScreen::kWelcome);
  EXPECT_TRUE(AnyContains(welcome.lines, "The device's own calibration, as it holds it now:"));
  EXPECT_TRUE(AnyContains(welcome.lines, "  AHRS_ORIENTATION 10 (ROLL_180_YAW_90)"));
  ToNoiseFloor(rig.engine);
  EXPECT_EQ(rig.journal->Inputs().at(kWelcomeStepId).at(welcome_key::kDeviceCalibration),
            "INS_ACCOFFS: x 0.3, y 0, z 0 m/s^2\nAHRS_ORIENTATION 10 (ROLL_180_YAW_90)");
  EXPECT_FALSE(AnyContains(rig.engine.View().lines, "The device's own calibration"));  // the welcome's only
}

// Resumed: what the device holds now is said again, and a change since the session began too.
TEST(WizardDeviceHooks, AResumedSessionSaysTheDevicesCalibrationAndWhetherItChanged) {
  std::shared_ptr<SessionJournal> journal;
  {
    DeviceRig first(StaticsThenWriteBack(), WithDeviceLines({"INS_ACCOFFS: x 0.3, y 0, z 0 m/s^2"}));
    ToNoiseFloor(first.engine);
    journal = first.journal;
  }
  DeviceRig same(StaticsThenWriteBack(), WithDeviceLines({"INS_ACCOFFS: x 0.3, y 0, z 0 m/s^2"}), journal);
  std::vector<std::string> lines = same.engine.View().lines;
  EXPECT_TRUE(AnyContains(lines, "Resuming session"));
  EXPECT_TRUE(AnyContains(lines, "  INS_ACCOFFS: x 0.3, y 0, z 0 m/s^2"));
  EXPECT_FALSE(AnyContains(lines, "It is not what the device held"));
  DeviceRig changed(StaticsThenWriteBack(), WithDeviceLines({"INS_ACCOFFS: x 0.1, y 0, z 0 m/s^2"}), journal);
  lines = changed.engine.View().lines;
  EXPECT_TRUE(AnyContains(lines, "  INS_ACCOFFS: x 0.1, y 0, z 0 m/s^2"));
  EXPECT_TRUE(AnyContains(lines, "It is not what the device held when the session began:"));
  EXPECT_TRUE(AnyContains(lines, "  INS_ACCOFFS: x 0.3, y 0, z 0 m/s^2"));
}

TEST(WizardDeviceHooks, ASourceWithoutADeviceSaysAndRecordsNothingOfIt) {
  DeviceRig rig(StaticsThenWriteBack());
  EXPECT_FALSE(AnyContains(rig.engine.View().lines, "own calibration"));
  ToNoiseFloor(rig.engine);
  EXPECT_EQ(rig.journal->Inputs().at(kWelcomeStepId).count(welcome_key::kDeviceCalibration), 0u);
}

// The sim's floor is about 1.5 counts: steps of 1 count limit it, steps of 0.5 do not.
TEST(WizardDeviceHooks, TheResolutionIsSaidAtTheNoiseFloorWhereItLimitsIt) {
  DeviceRig coarse(StaticsThenWriteBack());
  coarse.device.resolution_counts = 1.0;
  ToNoiseFloor(coarse.engine);
  coarse.engine.Handle({IntentKind::kAccept, ""});
  PollUntilQuestion(coarse.engine);
  const WizardView v = coarse.engine.View();
  ASSERT_FALSE(v.noise_floor_text.empty()) << v.problem;
  EXPECT_TRUE(AnyContains(v.lines, "Limited by the resolution: the readings come in steps of 1 counts: a noise "
                                   "below 0.289 counts (step / sqrt 12) is the rounding"))
      << ::testing::PrintToString(v.lines);
  EXPECT_TRUE(AnyContains({coarse.journal->Inputs().at(kNoiseFloorStepId).at(noise_floor_key::kResolution)},
                          "steps of 1 counts"));

  DeviceRig fine(StaticsThenWriteBack());
  fine.device.resolution_counts = 0.5;
  ToNoiseFloor(fine.engine);
  fine.engine.Handle({IntentKind::kAccept, ""});
  PollUntilQuestion(fine.engine);
  ASSERT_FALSE(fine.engine.View().noise_floor_text.empty());
  EXPECT_FALSE(AnyContains(fine.engine.View().lines, "resolution"));
  EXPECT_EQ(fine.journal->Inputs().at(kNoiseFloorStepId).count(noise_floor_key::kResolution), 0u);
}

TEST(WizardDeviceHooks, ANoticeOfTheSourceIsOnScreenInWordsUntilAKey) {
  DeviceRig rig(StaticsThenWriteBack());
  ToNoiseFloor(rig.engine);
  rig.device.next_notice = "tcp:127.0.0.1:5760: system 1 component 1 (ArduPilot) rebooted (its clock went back)";
  rig.device.next_kind = SourceNoticeKind::kRestarted;
  rig.engine.Poll(0.0);
  WizardView v = rig.engine.View();
  EXPECT_EQ(v.source_notice.rfind("The device restarted", 0), 0u) << v.source_notice;
  EXPECT_NE(v.source_detail.find("rebooted (its clock went back)"), std::string::npos) << v.source_detail;
  EXPECT_NE(v.source_detail.find("samples"), std::string::npos) << "the counts beside it: " << v.source_detail;
  rig.engine.Poll(0.0);
  EXPECT_FALSE(rig.engine.View().source_notice.empty()) << "it stays until a key";
  rig.engine.Handle({IntentKind::kAccept, ""});
  EXPECT_TRUE(rig.engine.View().source_notice.empty());
}

TEST(SourceNotices, LostSamplesAreSaidAtEachPowerOfTen) {
  SourceNotices notices;
  SourceStatus status;
  status.lost_frames = 1;
  notices.Update({}, status);
  EXPECT_NE(notices.text().find("Samples are being lost between the device and this computer (1 so far)"),
            std::string::npos) << notices.text();
  notices.Acknowledge();
  for (long lost : {2L, 5L, 9L}) {
    status.lost_frames = lost;
    notices.Update({}, status);
    EXPECT_TRUE(notices.text().empty()) << lost;
  }
  status.lost_frames = 12;
  notices.Update({}, status);
  EXPECT_NE(notices.text().find("(12 so far)"), std::string::npos) << notices.text();
  EXPECT_NE(notices.detail().find("12 samples lost"), std::string::npos) << notices.detail();
}

TEST(SourceNotices, EachKindHasItsWordsAndTheLinkItsComingsAndGoings) {
  for (SourceNoticeKind kind : {SourceNoticeKind::kRestarted, SourceNoticeKind::kRateRequest,
                                SourceNoticeKind::kCoarserReadings, SourceNoticeKind::kDeviceSilent,
                                SourceNoticeKind::kSamplesLost, SourceNoticeKind::kOther})
    EXPECT_FALSE(SourceNoticeWords(kind).empty());
  SourceNotices notices;
  SourceStatus status;
  status.link_error = "read /dev/ttyACM0: Input/output error";
  ReadResult lost;
  lost.link_lost = true;
  notices.Update(lost, status);
  EXPECT_EQ(notices.text(), "The link to the device was lost; the wizard is trying to reconnect.");
  EXPECT_NE(notices.detail().find("Input/output error"), std::string::npos);
  ReadResult back;
  back.reconnected = true;
  notices.Update(back, {});
  EXPECT_EQ(notices.text(), "The link to the device is back; samples arrive again.");
  // An IIO overrun is a notice of lost samples: said once by the count, with the source's words.
  SourceStatus overrun;
  overrun.lost_frames = 3;
  overrun.last_notice = "iio:adxl345: 3 samples lost between t = 1.0 s and 1.04 s (buffer overrun ...)";
  overrun.last_notice_kind = SourceNoticeKind::kSamplesLost;
  ReadResult noticed;
  noticed.notice = true;
  SourceNotices iio;
  iio.Update(noticed, overrun);
  EXPECT_NE(iio.text().find("(3 so far)"), std::string::npos) << iio.text();
  EXPECT_NE(iio.detail().find("buffer overrun"), std::string::npos) << iio.detail();
}

// On a source that is no MAVLink vehicle the write-back says so, and Enter finishes the session.
TEST(WizardDeviceHooks, TheWriteBackOnASourceThatIsNoVehicleHasNothingToWrite) {
  DeviceRig rig(StaticsThenWriteBack());
  AcceptUntil(rig.engine, [](const WizardView& v) { return v.step_title == "Write the calibration into the vehicle"; });
  const WizardView v = rig.engine.View();
  ASSERT_EQ(v.step_title, "Write the calibration into the vehicle");
  EXPECT_TRUE(AnyContains(v.lines, "The source is not a MAVLink vehicle"));
  EXPECT_FALSE(v.input.has_value()) << "nothing is asked";
  ASSERT_TRUE(rig.journal->Result().has_value()) << "the report recorded its calibration before";
  AcceptUntil(rig.engine, testing::Never);
  EXPECT_TRUE(rig.engine.View().finished);
  EXPECT_TRUE(rig.engine.completed());
  EXPECT_EQ(rig.journal->DoneSteps().at("write_back"), "nothing to write");
}

// The report's prompt says a step still follows it.
TEST(WizardDeviceHooks, TheReportSaysAStepFollowsIt) {
  DeviceRig rig(StaticsThenWriteBack());
  AcceptUntil(rig.engine, [](const WizardView& v) { return v.screen == WizardScreen::kReport && v.step_title == "Calibration report"; });
  EXPECT_EQ(rig.engine.View().prompt, "Calibration recorded in the session; press Enter to go on.");
}

TEST(WizardDeviceHooks, AWriteBackStepComesAfterTheReport) {
  // The shipped autopilot procedure with a write-back before its first step.
  std::ifstream shipped_file(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/autopilot_imu.toml");
  std::string text((std::istreambuf_iterator<char>(shipped_file)), std::istreambuf_iterator<char>());
  text.insert(text.find("[[step]]"), "[[step]]\nid = \"w\"\nkind = \"write_back\"\n\n");
  const std::string path = ::testing::TempDir() + "/write_back_first.toml";
  std::ofstream(path) << text;
  try {
    LoadProcedure(path);
    FAIL() << "a write_back before the report was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("a write_back step comes after the report step"), std::string::npos)
        << e.what();
  }
  const Procedure shipped = LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/autopilot_imu.toml");
  EXPECT_EQ(shipped.steps.back().kind, *StringToStepKind("write_back"));
  EXPECT_FALSE(shipped.steps.back().required);
}

}  // namespace
}  // namespace accelcal::wizard_device_hooks_test

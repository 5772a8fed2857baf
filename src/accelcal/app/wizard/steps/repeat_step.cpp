// A pose of the prism taken again (kind "repeat", `of` = an earlier static step's id), at the end
// of the session or between turntable runs (`on = "turntable"`: on the stopped turntable, the
// sensor left as it was mounted for the run before, which must hold the pose's up axis up: no
// remounting, the technician's time spent is the capture alone; the comparison is along gravity,
// which a different seat does not move to first order, calibration/pose_repeat.h): what moved since the first time is measured rather
// than guessed (a drift or a wandering bias, a sensor not yet warm, hysteresis after the
// turntable, a prism or mount that moved). The step takes the earlier step's pose, capture length
// and timeout. Its capture is kept for the fit like any pose: a disagreement between the two is
// scatter the fit's uncertainty must cover (calibration/excess_scatter.h) and a drift the
// diagnosis can see; the next screen says how far the reading moved against what the noise
// explains (calibration/pose_repeat.h).
//
// The whole kind is this file and its line in step_registry.cpp's list (ARCHITECTURE.md, "How to
// add a step kind").
#include <algorithm>
#include <iterator>
#include <memory>

#include <fmt/core.h>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/app/wizard/pose_setting.h"
#include "accelcal/app/wizard/settling_wait.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/acquiring_step.h"
#include "accelcal/calibration/pose_repeat.h"

namespace accelcal {
namespace {

// ---- the kind's fields in the procedure file ---------------------------------------------------

struct RepeatFields final : StepOwnFields {
  std::string of;  // the earlier static step whose pose is taken again
  bool on_turntable = false;  // on the stopped turntable, as mounted for the run before
};

const RepeatFields& RepeatOf(const ProcedureStep& step) {
  return dynamic_cast<const RepeatFields&>(*step.own_fields);
}

void ReadRepeatFields(StepFields& fields, ProcedureStep& step, const StepDefaults&) {
  auto own = std::make_shared<RepeatFields>();
  own->of = fields.Text("of", std::nullopt);
  const std::string on = fields.Text("on", std::string("prism"));
  if (on != "prism" && on != "turntable") fields.Fail("on", "'" + on + "' is neither \"prism\" nor \"turntable\"");
  own->on_turntable = on == "turntable";
  step.own_fields = std::move(own);
}

// On the turntable: the step before is a turntable run whose up axis is the pose's up, so the
// stopped table holds the sensor in the pose without remounting.
void CheckTurntableSeat(const ProcedureStep& step, const std::vector<ProcedureStep>& earlier, StepFields& fields) {
  if (earlier.empty() || earlier.back().kind != StepKind::kTurntable)
    fields.Fail("on", "\"turntable\" needs a turntable run right before the repeat");
  if (SensorAxisVector(earlier.back().up_axis).dot(step.up) < 1.0 - 1e-9)
    fields.Fail("on", "the turntable run before holds another axis up than '" + step.pose_name + "'");
}

// `of` names an earlier static pose: the repeat takes its pose, its capture length and timeout,
// and (without a title of its own) the title "<pose> again".
void CompleteRepeat(ProcedureStep& step, const std::vector<ProcedureStep>& earlier, StepFields& fields) {
  const std::string& of = RepeatOf(step).of;
  const auto first = std::find_if(earlier.begin(), earlier.end(), [&](const ProcedureStep& e) {
    return e.id == of && IsStaticPoseStep(e.kind);
  });
  if (first == earlier.end()) fields.Fail("of", "'" + of + "' is not an earlier static pose");
  step.up = first->up;
  step.pose_name = first->pose_name;
  step.duration_s = first->duration_s;
  step.timeout_s = first->timeout_s;
  if (!fields.Has("title"))
    step.title = first->pose_name + (RepeatOf(step).on_turntable ? " again, on the stopped turntable" : " again");
  if (RepeatOf(step).on_turntable) CheckTurntableSeat(step, earlier, fields);
}

// ---- the controller -------------------------------------------------------------------------------

class RepeatStep final : public AcquiringStep {
 public:
  using AcquiringStep::AcquiringStep;

 protected:
  // The pose was captured before: taking it again is the point.
  bool ChecksDuplicates() const override { return false; }

  // The plan's length, ended by its stop rule (bench_plan.h: a capture like any pose); before
  // the capture starts, as long as the session's captures say the sensor needs to settle.
  CaptureRequest MakeRequest() const override {
    CaptureRequest r = Planned(AcquiringStep::MakeRequest());
    AddSettlingWait(session_, r);
    return r;
  }
  double CaptureS() const override { return session_.bench_plan.CaptureS(step_); }

  void OnCaptureAccepted(Capture capture) override {
    KeepCapture(capture);
    if (const JournalCapture* first = session_.model.CaptureOf(RepeatOf(step_).of))
      session_.screen.notice += fmt::format("; since the first time the reading {}",
                                            DescribePoseRepeat(ComparePoseRepeat(first->capture, capture, session_.procedure.nominal)));
    session_.captured.push_back({capture.id, capture.label, session_.MeasuredUp(capture)});
    session_.noise_floor.Recheck(capture, session_.captured);
    session_.next_capture_id = capture.id + 1;
    session_.sequence.ContinueFromFirstOpenStep();
  }

  // On the stopped turntable when the run right before it has its capture: the sensor is still
  // mounted with the pose's up axis up. A run skipped (by s, or left out by the capture plan)
  // mounted nothing, so the pose is set on the prism as the first time.
  bool OnStoppedTurntable() const {
    if (!RepeatOf(step_).on_turntable) return false;
    const std::vector<ProcedureStep>& steps = session_.procedure.steps;
    const auto at = std::find_if(steps.begin(), steps.end(), [&](const ProcedureStep& s) { return s.id == step_.id; });
    return at != steps.begin() && at != steps.end() && session_.model.CaptureOf(std::prev(at)->id) != nullptr;
  }

  // On the turntable: the table stops with the sensor as mounted (the virtual bench's too).
  void PlaceOnBench() override {
    if (!OnStoppedTurntable()) return AcquiringStep::PlaceOnBench();
    if (BenchControl* bench = session_.source.bench()) bench->StopTurntable();
  }

  void SetPlaceView(WizardView& v) const override {
    v.screen = WizardScreen::kPlacePose;
    if (OnStoppedTurntable()) {
      v.prompt = fmt::format("The first pose again ({}), on the turntable: stop the table and leave the sensor "
                             "as it is mounted; what moved since the first time is measured. Press Enter to capture.",
                             step_.pose_name);
      v.keys = WithNavigation({{"Enter", "capture"}});
      return;
    }
    const std::string how = IsTiltedPose(step_.up) ? "Set the prism " + PrismSetting(step_.up, step_.pose_name)
                                                   : "Put the prism on the table with " + step_.pose_name;
    const std::string why = RepeatOf(step_).on_turntable ? " (the turntable run before it was not taken: nothing is mounted)" : "";
    v.prompt = fmt::format("{} again, as for the first pose{}, and let go: what moved since is measured. "
                           "Press Enter to capture.", how, why);
    v.keys = WithNavigation({{"Enter", "capture"}});
  }
};

// On the stopped turntable nothing is placed: the settle window and the capture.
double RepeatEstimateS(const ProcedureStep& step, const TimeAllowances& a) {
  return RepeatOf(step).on_turntable ? a.settle_s + step.duration_s : PlacedStepEstimateS(step, a);
}

}  // namespace

StepKindDefinition RepeatStepKind() {
  return {{"repeat", StepAcquires::kStaticCapture, true, false, "", &ReadRepeatFields, &CompleteRepeat},
          {StepKind{}, &MakeStepController<RepeatStep>, &RepeatEstimateS, nullptr, nullptr}};
}

}  // namespace accelcal

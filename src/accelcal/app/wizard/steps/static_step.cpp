// A static pose of the prism (kind "static"): placed as asked (a face up, or set on an edge or a
// corner for a tilted pose: pose_setting.h), captured still, in the expected orientation and not
// a pose already captured. The accepted capture is kept for the fit and checks the session's
// noise floor (noise_floor_step.h); taken again on the way back (a redo).
#include <fmt/core.h>

#include "accelcal/app/wizard/pose_setting.h"
#include "accelcal/app/wizard/settling_wait.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/acquiring_step.h"

namespace accelcal {
namespace {

class StaticStep final : public AcquiringStep {
 public:
  using AcquiringStep::AcquiringStep;

 protected:
  void OnCaptureAccepted(Capture capture) override {
    KeepCapture(capture);
    session_.captured.push_back({capture.id, capture.label, session_.MeasuredUp(capture)});
    session_.noise_floor.Recheck(capture, session_.captured);
    session_.next_capture_id = capture.id + 1;
    session_.sequence.ContinueFromFirstOpenStep();
  }

  // The plan's length, ended by its stop rule (bench_plan.h); before the capture starts, as long
  // as the session's captures say the sensor needs to settle.
  CaptureRequest MakeRequest() const override {
    CaptureRequest r = Planned(AcquiringStep::MakeRequest());
    AddSettlingWait(session_, r);
    return r;
  }
  double CaptureS() const override { return session_.bench_plan.CaptureS(step_); }

  void SetPlaceView(WizardView& v) const override {
    v.screen = WizardScreen::kPlacePose;
    v.prompt = IsTiltedPose(step_.up)
                   ? fmt::format("Set the prism {} and let go; press Enter to capture.",
                                 PrismSetting(step_.up, step_.pose_name))
                   : fmt::format("Put the prism on the table with {} and let go; press Enter to capture.",
                                 step_.pose_name);
    v.keys = WithNavigation({{"Enter", "capture"}});
  }
};

}  // namespace

StepControllerKind StaticStepKind() {
  return {StepKind::kStatic, &MakeStepController<StaticStep>, &PlacedStepEstimateS, nullptr, nullptr};
}

}  // namespace accelcal

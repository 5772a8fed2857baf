// The leveling step (kind "level"): the reversal method. The prism +z up is measured, turned 180
// deg about the vertical and measured again: the difference is the table's tilt, the mean the
// sensor's own offset (leveling.h). Not level: the technician turns the feet as advised (on the
// virtual bench, its technician does) and measures again. The live tilt is shown while the step
// runs, without the sensor's offset once a reversal has measured it.
#include <cmath>
#include <optional>

#include <fmt/core.h>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/app/wizard/leveling.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/acquiring_step.h"

namespace accelcal {
namespace {

class LevelStep final : public AcquiringStep {
 public:
  using AcquiringStep::AcquiringStep;

  void Enter() override {
    first_counts_.reset();
    EnterPlace();
  }

  bool BackWithin() override {
    if (phase_ != Phase::kOwn) return AcquiringStep::BackWithin();
    if (result_) return false;
    EnterPlace();  // from the turn: the first reading again
    return true;
  }

  WizardScreen PlaceScreen() const override { return WizardScreen::kLevel; }

  // The live tilt, without the sensor's own offset once a reversal has measured it (before, it
  // includes the offset: adjusting the feet by it chases the offset).
  void AddLive(WizardView& v, bool on_screen) const override {
    if ((on_screen && phase_ == Phase::kOwn && result_) || !session_.live_counts.allFinite()) return;
    const SensorModel& rough = session_.procedure.nominal;
    if (offset_) {
      v.tilt_deg = TiltWithoutOffsetDeg(session_.live_counts, rough, *offset_);
      const Eigen::Vector2d offset_deg = OffsetAsTiltDeg(*offset_);
      v.tilt_note = fmt::format("sensor's offset (x {:.1f}, y {:.1f} deg) taken out", offset_deg.x(), offset_deg.y());
    } else {
      v.tilt_deg = ApparentTiltDeg(session_.live_counts, rough);
      v.tilt_note = "includes the sensor's offset until the reversal";
    }
  }

 protected:
  // The second reading: the prism turned 180 deg about the vertical.
  void PlaceOnBench() override {
    if (BenchControl* bench = session_.source.bench()) bench->PlaceStatic(step_.up, first_counts_ ? M_PI : 0.0);
  }

  bool ChecksDuplicates() const override { return false; }

  void OnCaptureAccepted(Capture capture) override {
    const Eigen::Vector3d& mean_counts = capture.stats().mean_counts;
    if (!first_counts_) {
      first_counts_ = mean_counts;
      phase_ = Phase::kOwn;
      result_ = false;
      return;
    }
    const SensorModel& rough = session_.procedure.nominal;
    tilt_deg_ = ReversalTiltDeg(*first_counts_, mean_counts, rough);
    offset_ = ReversalOffset(*first_counts_, mean_counts, rough);
    const std::string advice = LevelingAdvice(tilt_deg_, step_.tolerance_deg);
    level_ = advice.empty();
    session_.screen.problem = level_ ? "" : "the table is not level: " + advice;
    session_.screen.hint = level_ ? "" : "adjust the feet, then Enter to measure again (s skips leveling)";
    first_counts_.reset();
    phase_ = Phase::kOwn;
    result_ = true;
  }

  void HandleOwn(const Intent& intent) override {
    if (intent.kind == IntentKind::kSkip) return session_.sequence.AskSkip();
    if (intent.kind == IntentKind::kBack) return session_.sequence.GoBack();
    const bool accept = intent.kind == IntentKind::kAccept || intent.kind == IntentKind::kSubmitText;
    if (!result_) {  // turned: measure again
      if (accept || intent.kind == IntentKind::kRetry) Begin();
      return;
    }
    if (intent.kind == IntentKind::kRetry) return EnterPlace();
    if (accept && !level_) {
      // The operator turns the feet as advised (on the virtual bench, its technician does).
      if (BenchControl* bench = session_.source.bench()) bench->AdjustTableFeet(tilt_deg_);
      return EnterPlace();
    }
    if (accept)
      session_.sequence.FinishStep(
          fmt::format("level: tilt {:.2f} deg about x, {:.2f} deg about y", tilt_deg_.x(), tilt_deg_.y()));
  }

  void SetPlaceView(WizardView& v) const override {
    v.screen = WizardScreen::kLevel;
    v.prompt = "Put the prism on the table with +z up and let go; press Enter to measure the tilt.";
    v.keys = WithNavigation({{"Enter", "capture"}});
  }

  void SetOwnView(WizardView& v) const override {
    v.screen = WizardScreen::kLevel;
    if (!result_) {
      v.prompt = "Turn the prism 180 deg about the vertical (still +z up); press Enter to measure again.";
      v.keys = WithNavigation({{"Enter", "measure"}});
      return;
    }
    v.tilt_deg = tilt_deg_;
    v.prompt = fmt::format("Tilt {:.2f} deg about x, {:.2f} deg about y (tolerance {:g} deg): {}.", tilt_deg_.x(),
                           tilt_deg_.y(), step_.tolerance_deg,
                           level_ ? "level; press Enter to continue" : "not level");
    v.keys = WithNavigation({{"Enter", level_ ? "continue" : "measure again"}, {"r", "measure again"}});
  }

 private:
  // kOwn: the first reading is taken and the prism is to be turned (!result_), or the tilt is
  // shown (result_).
  bool result_ = false;
  std::optional<Eigen::Vector3d> first_counts_;  // the first reading's mean, counts
  Eigen::Vector2d tilt_deg_ = Eigen::Vector2d::Constant(kNaN);
  bool level_ = false;
  // The sensor's own offset measured by the last reversal (leveling.h): taken out of the live tilt.
  std::optional<Eigen::Vector2d> offset_;
};

double LevelEstimateS(const ProcedureStep& step, const TimeAllowances& a) {
  return a.level_s + 2.0 * (a.settle_s + step.duration_s);
}

}  // namespace

StepControllerKind LevelStepKind() {
  return {StepKind::kLevel, &MakeStepController<LevelStep>, &LevelEstimateS, nullptr, nullptr};
}

}  // namespace accelcal

#include "accelcal/app/wizard/steps/noise_floor_step.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/app/wizard/session_settings.h"
#include "accelcal/app/wizard/step_controller.h"
#include "accelcal/app/wizard/wizard_session.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {
namespace {

// The capture engine's stillness check as the procedure sets it.
StaticStabilityOptions ProcedureStability(const Procedure& p) {
  StaticStabilityOptions o;
  o.std_multiplier = p.std_multiplier;
  o.trend_multiplier = p.trend_multiplier;
  return o;
}

}  // namespace

NoiseFloorStep::NoiseFloorStep(const Procedure& procedure, SessionModel& model, StepAcquisition& acq,
                               ScreenMessages& screen, double quiet_period_s, const SampleSource* source)
    : procedure_(procedure), model_(model), acq_(acq), screen_(screen), quiet_period_s_(quiet_period_s),
      source_(source),
      guard_(procedure.expected_noise_counts, procedure.noise_floor_max_ratio, ProcedureStability(procedure)) {}

// A floor lowered in an earlier run stays: the captures were judged again with it. Read as
// `accelcal refit` reads it (session_settings.h).
void NoiseFloorStep::Resume() {
  if (std::optional<NoiseFloor> lowered = RecordedLoweredFloor(model_.inputs())) lowered_ = std::move(lowered);
}

void NoiseFloorStep::Measure(double timeout_s) {
  acq_.MeasureNoiseFloor(SteadyNowS(), timeout_s);
  measuring_ = true;
}

bool NoiseFloorStep::OnMeasured() {
  measuring_ = false;
  const NoiseFloorJudgement j = guard_.Judge(acq_.quiet_samples());
  if (!j.ok) {
    screen_.problem = j.reason;
    screen_.hint = "keep hands off the bench and stop what shakes it, then Enter measures again";
    Refused("keep hands off the bench and stop what shakes it (or check that the procedure's "
            "expected noise is this sensor's)", false);
    return false;
  }
  refusals_in_row_ = silent_in_row_ = 0;
  first_refused_t_s_ = kNaN;
  gives_up_ = false;
  // A lower floor of an earlier run (proved by its captures) wins over a new measurement above it.
  if (lowered_) {
    NoiseFloor f = *guard_.floor();
    for (int a = 0; a < 3; ++a) f.std_counts[a] = std::min(f.std_counts[a], lowered_->std_counts[a]);
    if (f.std_counts != guard_.floor()->std_counts) f.source += ", with the lower floor of an earlier run";
    guard_.Restore(f);
  }
  screen_.problem.clear();
  screen_.hint.clear();
  model_.RecordInput(kNoiseFloorStepId, noise_floor_key::kStdCounts, TriadText(guard_.floor()->std_counts));
  lines_ = {"Noise floor: " + guard_.Describe()};
  if (const std::string limit = ResolutionLimit(); !limit.empty()) {
    lines_.push_back(limit);
    model_.RecordInput(kNoiseFloorStepId, noise_floor_key::kResolution, limit);
  }
  return true;
}

// The floor is limited by the stream's resolution when an axis's floor is not well above its
// step: below a step the rounding is most of what is measured (step / sqrt 12 of it when the
// noise dithers the rounding, anything from 0 to step / 2 when it does not).
std::string NoiseFloorStep::ResolutionLimit() const {
  if (source_ == nullptr || !guard_.floor()) return "";
  const SourceStatus& status = source_->status();
  const double step = status.resolution_counts;
  if (!(step > 0.0)) return "";
  if (guard_.floor()->std_counts.minCoeff() >= 2.0 * step) return "";
  return fmt::format("Limited by the resolution: {} (the floor measured is within two steps of it).",
                     status.ResolutionNote());
}

void NoiseFloorStep::OnSilent() {
  measuring_ = false;
  screen_.problem = acq_.reason();
  screen_.hint = "check the cable or the sample server; Enter measures again, q leaves";
  Refused("check the cable or the sample server", true);
}

// A measurement refused: once the floor has been refused for kRefusedLongestS of the bench's
// clock (or silent kSilentBeforeLeaving times) in a row, the same bench measured again will not
// do, and Enter saves and quits instead (a loop of Enter would never end).
void NoiseFloorStep::Refused(const std::string& check, bool silent) {
  ++refusals_in_row_;
  silent_in_row_ = silent ? silent_in_row_ + 1 : 0;
  const std::vector<Sample>& quiet = acq_.quiet_samples();
  double refused_for_s = 0.0;
  if (!quiet.empty()) {
    if (!std::isfinite(first_refused_t_s_)) first_refused_t_s_ = quiet.front().t_s;
    refused_for_s = quiet.back().t_s - first_refused_t_s_;
  }
  gives_up_ = silent_in_row_ >= kSilentBeforeLeaving || refused_for_s >= kRefusedLongestS;
  if (!gives_up_) return;
  screen_.hint = fmt::format("not accepted {} times in a row ({:.0f} s): {} (the same again will not do); r "
                             "measures again, Enter saves and quits (the session resumes here)",
                             refusals_in_row_, refused_for_s, check);
}

void NoiseFloorStep::SetView(WizardView& v) const {
  if (!measuring_ && gives_up_) {
    v.screen = WizardScreen::kPlacePose;
    v.prompt = fmt::format("The noise floor was not accepted {} times in a row.", refusals_in_row_);
    v.keys = WithNavigation({{"r", "measure again"}, {"Enter", "save and quit"}});
    return;
  }
  if (!measuring_) {
    v.screen = WizardScreen::kPlacePose;
    v.prompt = fmt::format(
        "Noise floor: leave the sensor resting on the table, hands off, nothing shaking the bench "
        "(turntable stopped); press Enter to measure it ({:g} s).", quiet_period_s_);
    v.keys = WithNavigation({{"Enter", "measure"}});
    return;
  }
  v.screen = WizardScreen::kCapturing;
  v.prompt = fmt::format("Leave the sensor resting on the table: measuring the noise floor ({:g} s).",
                         quiet_period_s_);
  v.progress = acq_.quiet_progress();
  v.keys = {{"q", "save and quit"}};
}

// After a static capture: the floor checked against it, lowered if it proves too high, and
// the captures judged with the old floor judged again; those that fail are left out and their
// steps captured again.
void NoiseFloorStep::Recheck(const Capture& latest, std::vector<CapturedPose>& captured) {
  std::vector<const Capture*> used;
  for (const JournalCapture& c : model_.captures())
    if (c.capture.kind == CaptureKind::kStatic && model_.LeftOutReason(c).empty() && !c.superseded())
      used.push_back(&c.capture);
  const NoiseFloorRecheck r = guard_.Recheck(latest, used);
  if (!r.lowered) return;
  model_.RecordInput(kNoiseFloorStepId, noise_floor_key::kLoweredStdCounts, TriadText(r.after.std_counts));
  model_.RecordInput(kNoiseFloorStepId, noise_floor_key::kLowered, r.note);
  lowered_ = r.after;
  lines_ = {"Noise floor: " + guard_.Describe(), r.note};
  std::vector<std::string> again;
  for (const RejudgedCapture& f : r.failing) {
    for (const JournalCapture& c : model_.captures()) {
      if (c.capture.id != f.capture_id) continue;
      model_.MarkLeftOut(c, f.reason + " (judged again against the lowered noise floor)");
      again.push_back(c.capture.label);
      std::erase_if(captured, [&](const CapturedPose& p) { return p.capture_id == c.capture.id; });
    }
  }
  if (!again.empty())
    lines_.push_back(fmt::format("Judged again with it, not still after all, left out and to be "
                                 "captured again: {}.", fmt::join(again, ", ")));
}

}  // namespace accelcal

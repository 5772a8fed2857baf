// The wizard engine's capture flow in the technician's terms: the time left (this capture, its
// give-up, the session's estimate) on every screen, and the confirmation of an accepted capture
// with its figures. The words for the capture's state are in capture_messages.h, the estimate in
// time_estimate.h.
#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/app/wizard/time_estimate.h"
#include "accelcal/app/wizard/wizard_engine.h"

namespace accelcal {
namespace {

bool HasCapture(StepKind kind) {
  return kind == StepKind::kStatic || kind == StepKind::kTurntable || kind == StepKind::kLevel;
}

}  // namespace

// The steps not yet recorded from the current one (or the next, once the current one runs).
double WizardEngine::SessionLeftS(bool current_started) const {
  const int first = current_started ? current_ + 1 : current_;
  return RemainingEstimateS(procedure_, first,
                            [this](const ProcedureStep& s) { return StepRecorded(s.id); });
}

// Every screen but the final one says the time; a running capture has set its own
// (SetCaptureView: it knows the capture's progress).
void WizardEngine::SetTimeView(WizardView& v) const {
  if (phase_ == Phase::kDone || !v.time_text.empty()) return;
  const int n = static_cast<int>(procedure_.steps.size());
  if (current_ < 0 || current_ >= n) {
    v.session_left_s = SessionLeftS(false);
    v.time_text = WaitingTimeText(kNaN, kNaN, v.session_left_s);
    return;
  }
  if (phase_ == Phase::kRecord && v.record) {
    v.session_left_s = std::max(v.record->duration_s - v.record->elapsed_s, 0.0) + SessionLeftS(true);
    v.time_text = WaitingTimeText(kNaN, kNaN, v.session_left_s);
    return;
  }
  v.session_left_s = SessionLeftS(false);
  const bool capture = HasCapture(step().kind) && phase_ != Phase::kResult &&
                       phase_ != Phase::kQuiet && phase_ != Phase::kQuietReady;
  v.time_text = WaitingTimeText(capture ? step().duration_s : kNaN, step().timeout_s, v.session_left_s);
}

// Said on the next screen until a key: what was taken, with its figures. |a| is from the
// procedure's nominal (datasheet) model, the fit comes later: a few % off, said so.
void WizardEngine::ConfirmCapture(const Capture& capture) {
  const CaptureStats& st = capture.stats();
  const double covered_s =
      st.n > 1 ? (st.t_last_s - st.t_first_s) * static_cast<double>(st.n) / static_cast<double>(st.n - 1) : 0.0;
  const double a_mps2 = procedure_.nominal.Calibrate(st.mean_counts).norm();
  const double noise_counts = std::sqrt(st.StdCounts().squaredNorm() / 3.0);
  notice_ = fmt::format("{} done: {:.1f} s, |a| ~{:.2f} m/s^2 by the datasheet, noise {:.1f} counts", capture.label,
                        covered_s, a_mps2, noise_counts);
}

}  // namespace accelcal

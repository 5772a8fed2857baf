#include "accelcal/acquire/capture_engine/capture_engine.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

// Samples of a stream come every dt: n samples from t_first to t_last cover n dt.
double CoveredS(double t_first_s, double t_last_s, size_t n) {
  if (n < 2) return 0.0;
  const double span_s = t_last_s - t_first_s;
  return span_s + span_s / static_cast<double>(n - 1);
}

void ThrowIfInvalid(const std::string& what, const std::string& problem) {
  if (!problem.empty()) throw Error(what + ": " + problem);
}

}  // namespace

std::string_view CaptureStateToString(CaptureState state) {
  switch (state) {
    case CaptureState::kSettling: return "settling";
    case CaptureState::kCapturing: return "capturing";
    case CaptureState::kRetrying: return "retrying";
    case CaptureState::kAccepted: return "accepted";
    case CaptureState::kTimedOut: return "timed out";
    case CaptureState::kRejected: return "rejected";
  }
  return "?";
}

std::string CaptureEngineOptions::Validate() const {
  for (const std::string& e : {stability.Validate(), orientation.Validate(),
                               turntable.Validate(), screening.Validate()}) {
    if (!e.empty()) return e;
  }
  for (const double s : {settle_window_s, turntable_settle_window_s, check_interval_s,
                         turntable_check_interval_s}) {
    if (!(std::isfinite(s) && s > 0.0))
      return fmt::format("settle windows and check intervals must be > 0 s (got {})", s);
  }
  return {};
}

CaptureEngine::CaptureEngine(CaptureRequest request, const CaptureEngineOptions& options,
                             CaptureContext context)
    : request_(std::move(request)),
      options_(options),
      context_(std::move(context)),
      settle_(options.stability, context_.noise_floor, options.settle_window_s),
      capture_monitor_(options.stability, context_.noise_floor, StaticStabilityMonitor::kGrowing) {
  ThrowIfInvalid("capture request", request_.Validate());
  ThrowIfInvalid("capture options", options_.Validate());
  ThrowIfInvalid("capture context", context_.Validate());
  Restart();
}

void CaptureEngine::Restart() {
  state_ = CaptureState::kSettling;
  reason_.clear();
  settle_wait_.clear();
  attempts_ = 0;
  t_start_s_ = t_last_s_ = t_next_check_s_ = kNaN;
  settle_.Reset();
  capture_monitor_.Reset();
  turntable_window_.clear();
  live_ = StabilityVerdict{};
  retry_verdict_ = StabilityVerdict{};
  turntable_verdict_ = TurntableVerdict{};
  capture_ = Capture{};
  stats_ = CaptureStats{};
  if (request_.kind == CaptureKind::kTurntable && options_.screening.adc_range) {
    std::string problem = CheckTurntablePlan(request_.turntable, context_.rough_model,
                                             *options_.screening.adc_range, options_.turntable);
    if (!problem.empty()) Reject(std::move(problem));
  }
}

bool CaptureEngine::finished() const {
  return state_ == CaptureState::kAccepted || state_ == CaptureState::kTimedOut ||
         state_ == CaptureState::kRejected;
}

void CaptureEngine::Feed(const std::vector<Sample>& chunk) {
  for (const Sample& s : chunk) {
    if (finished()) return;
    Feed(s);
  }
}

void CaptureEngine::Feed(const Sample& s) {
  if (finished()) return;
  if (!IsFinite(s)) {
    // Screening words it ("1 sample is NaN or infinite (first at t = ...)").
    Capture one;
    one.samples = {s};
    ScreeningOptions screening = options_.screening;
    screening.min_samples = 0;
    Reject(ScreeningReason(one, screening));
    return;
  }
  if (std::isnan(t_start_s_)) t_start_s_ = t_next_check_s_ = s.t_s;
  t_last_s_ = s.t_s;
  if (request_.kind == CaptureKind::kStatic) {
    settle_.Add(s);
    FollowSpike(s);
  } else {
    turntable_window_.push_back(s);
  }
  if (state_ == CaptureState::kCapturing) {
    capture_.samples.push_back(s);
    stats_.Add(s);
    if (request_.kind == CaptureKind::kStatic) capture_monitor_.Add(s);
    if (CaptureComplete()) {
      FinishCapture();
      return;
    }
  }
  if (s.t_s >= t_next_check_s_) {
    const double interval_s = request_.kind == CaptureKind::kStatic
                                  ? options_.check_interval_s
                                  : options_.turntable_check_interval_s;
    t_next_check_s_ = s.t_s + interval_s;
    Check(s.t_s);
  }
}

void CaptureEngine::Check(double t_s) {
  if (state_ == CaptureState::kCapturing) {
    CheckCapturing();
    return;
  }
  if (t_s - t_start_s_ > request_.timeout_s) {
    state_ = CaptureState::kTimedOut;
    reason_ = fmt::format("no stable capture within {:.3g} s: last problem: {}",
                          request_.timeout_s, LastProblem());
    return;
  }
  if (request_.kind == CaptureKind::kStatic) {
    CheckSettledStatic(t_s);
  } else {
    CheckSettledTurntable(t_s);
  }
}

std::string CaptureEngine::LastProblem() const {
  if (request_.kind == CaptureKind::kTurntable) {
    if (!turntable_verdict_.reason.empty()) return turntable_verdict_.reason;
  } else if (live_.judged && !live_.stable) {
    return live_.reason;
  }
  if (!reason_.empty()) return reason_;
  return "no data long enough to judge";
}

bool CaptureEngine::RejectedForPose(const Eigen::Vector3d& mean_counts) {
  const OrientationVerdict pose =
      CheckOrientation(mean_counts, context_.rough_model, request_.expected, context_.captured,
                       context_.known_poses, options_.orientation);
  if (!pose.ok) Reject(pose.reason);
  return !pose.ok;
}

void CaptureEngine::CheckSettledStatic(double t_s) {
  live_ = settle_.Verdict();
  settle_wait_.clear();
  if (!settle_.full() || !live_.stable) return;
  if (RejectedForPose(live_.mean_counts)) return;
  // Still, in the right pose, but known to need longer to settle (the request's wait).
  if (const double left_s = request_.settle_wait_s - (t_s - t_start_s_); left_s > 0.0) {
    settle_wait_ = fmt::format("{}; waiting {:.0f} s more", request_.settle_wait_reason, std::ceil(left_s));
    return;
  }
  BeginCapture();
}

void CaptureEngine::TrimTurntableWindow(double t_s) {
  const double t_keep_s = t_s - options_.turntable_settle_window_s;
  const auto first_kept = std::find_if(turntable_window_.begin(), turntable_window_.end(),
                                       [&](const Sample& s) { return s.t_s > t_keep_s; });
  turntable_window_.erase(turntable_window_.begin(), first_kept);
}

void CaptureEngine::CheckSettledTurntable(double t_s) {
  // Samples older than one window are dropped here, at each check: the window holds at most
  // (window + check interval) x rate samples.
  const bool covered = t_s - t_start_s_ >= options_.turntable_settle_window_s;
  TrimTurntableWindow(t_s);
  if (!covered || turntable_window_.size() < 3) return;
  // The tilt is judged on the whole capture, not here: the window may still hold the hand's
  // shake of the mounting, whose tones near the table's speed would read as a swing.
  TurntableStabilityOptions settling = options_.turntable;
  settling.judge_tilt = false;
  turntable_verdict_ = EvaluateTurntable(turntable_window_, context_.rough_model,
                                         request_.turntable, settling);
  const TurntableVerdict& v = turntable_verdict_;
  if (v.ok) {
    BeginCapture();
  } else if (v.steady) {
    // Steady but wrong: waiting will not fix the mounting or the entered rpm and radius.
    Reject(v.reason);
  }
}

void CaptureEngine::CheckCapturing() {
  if (request_.kind != CaptureKind::kStatic) return;  // judged on the whole run at the end
  live_ = capture_monitor_.Verdict();
  if (live_.judged && !live_.stable) RetryUnstable();
}

void CaptureEngine::RetryUnstable() {
  Retry(live_.reason);
  retry_verdict_ = live_;
}

// The capture failed at the first check after a bump began, often on its rising edge; the
// bump goes on in the samples that follow. Its event is carried on from the failed capture's
// verdict (its monitor was reset), so that the reason names the bump's largest excursion from
// the level before it, not the reading the check happened to fall on. Only the words change:
// the capture was already given up.
void CaptureEngine::FollowSpike(const Sample& s) {
  if (state_ != CaptureState::kRetrying || !retry_verdict_.largest_spike) return;
  SpikeEvent& e = *retry_verdict_.largest_spike;
  // The settle window judged the reading as the capture would have: no spike there ends the
  // bump (a sensor set down on another face is a new level, not a bump that goes on).
  if (!settle_.last_reading_spiked()) {
    e.open = false;
    return;
  }
  if (ContinueSpikeEvent(&e, s, options_.stability.spike_sigmas)) reason_ = retry_verdict_.JudgedReason();
}

void CaptureEngine::BeginCapture() {
  state_ = CaptureState::kCapturing;
  ++attempts_;
  capture_ = Capture{};
  capture_.id = request_.id;
  capture_.kind = request_.kind;
  capture_.label = request_.label;
  if (request_.kind == CaptureKind::kTurntable) {
    capture_.radius_m = request_.turntable.radius_m;
    capture_.rpm = request_.turntable.rpm;
  }
  stats_ = CaptureStats{};
  capture_monitor_.Reset();
  retry_verdict_ = StabilityVerdict{};
}

bool CaptureEngine::CaptureComplete() const {
  if (capture_.samples.size() < 2) return false;
  if (request_.stop_samples > 0) return static_cast<long>(capture_.samples.size()) >= request_.stop_samples;
  return CoveredS(capture_.samples.front().t_s, capture_.samples.back().t_s,
                  capture_.samples.size()) >= request_.duration_s * (1.0 - 1e-9);
}

void CaptureEngine::FinishCapture() {
  capture_.set_stats(stats_);  // computed as the samples came: carried, never recomputed
  if (std::string screening = ScreeningReason(capture_, options_.screening); !screening.empty()) {
    Reject(std::move(screening));
    return;
  }
  if (request_.kind == CaptureKind::kStatic) {
    FinishStatic();
  } else {
    FinishTurntable();
  }
}

void CaptureEngine::FinishStatic() {
  live_ = capture_monitor_.Verdict();
  if (!live_.stable) {
    RetryUnstable();
    return;
  }
  if (RejectedForPose(stats_.mean_counts)) return;
  state_ = CaptureState::kAccepted;
  reason_.clear();
}

void CaptureEngine::FinishTurntable() {
  turntable_verdict_ = EvaluateTurntable(capture_.samples, context_.rough_model,
                                         request_.turntable, options_.turntable);
  if (turntable_verdict_.ok) {
    // The tilt's once-per-revolution swing is not the sensor's noise: out of the samples, so
    // that the statistics (and the fit's weight of this capture) are the sensor's.
    RemoveOncePerRevolution(&capture_.samples, turntable_verdict_.swing);
    stats_ = ComputeStats(capture_.samples);
    capture_.set_stats(stats_);
    state_ = CaptureState::kAccepted;
    reason_.clear();
  } else if (!turntable_verdict_.steady) {
    Retry(turntable_verdict_.reason);
  } else {
    Reject(turntable_verdict_.reason);
  }
}

void CaptureEngine::Retry(std::string reason) {
  state_ = CaptureState::kRetrying;
  reason_ = std::move(reason);
  capture_.samples.clear();
  capture_.samples.shrink_to_fit();
  stats_ = CaptureStats{};
  capture_monitor_.Reset();
}

void CaptureEngine::Reject(std::string reason) {
  state_ = CaptureState::kRejected;
  reason_ = std::move(reason);
}

CaptureSnapshot CaptureEngine::Snapshot() const {
  CaptureSnapshot snap;
  snap.state = state_;
  snap.attempts = attempts_;
  snap.elapsed_s = std::isnan(t_start_s_) ? 0.0 : t_last_s_ - t_start_s_;
  snap.stability = live_;
  snap.turntable = turntable_verdict_;
  if (state_ == CaptureState::kCapturing && !capture_.samples.empty()) {
    const double covered_s = CoveredS(capture_.samples.front().t_s, capture_.samples.back().t_s,
                                      capture_.samples.size());
    snap.progress = request_.stop_samples > 0
                        ? std::clamp(static_cast<double>(capture_.samples.size()) /
                                         static_cast<double>(request_.stop_samples), 0.0, 1.0)
                        : std::clamp(covered_s / request_.duration_s, 0.0, 1.0);
  } else if (state_ == CaptureState::kAccepted) {
    snap.progress = 1.0;
  }
  snap.reason = reason_;
  if (state_ == CaptureState::kSettling) {
    snap.reason = request_.kind == CaptureKind::kStatic ? live_.reason : turntable_verdict_.reason;
    snap.settle_wait = settle_wait_;
  }
  return snap;
}

}  // namespace accelcal

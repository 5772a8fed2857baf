#include "accelcal/app/wizard/step_acquisition.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/core.h>

namespace accelcal {

double SteadyNowS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

StepAcquisition::StepAcquisition(double quiet_period_s) : quiet_period_s_(quiet_period_s) {}

void StepAcquisition::MeasureNoiseFloor(double wall_now_s, double timeout_s) {
  Stop();
  timeout_s_ = timeout_s;
  last_sample_wall_s_ = wall_now_s;
  quiet_samples_.clear();
  quiet_ = CaptureStats();
}

void StepAcquisition::StartCapture(const CaptureRequest& request, const CaptureEngineOptions& options,
                                   const CaptureContext& context, double wall_now_s) {
  Stop();
  capture_ = std::make_unique<CaptureEngine>(request, options, context);
  timeout_s_ = request.timeout_s;
  capture_wall_start_s_ = last_sample_wall_s_ = wall_now_s;
  reason_.clear();
  ended_silent_ = false;
}

void StepAcquisition::StartRecord(std::unique_ptr<RecordStepWriter> record, bool settle,
                                  double wall_now_s, double silence_timeout_s) {
  Stop();
  record_ = std::move(record);
  timeout_s_ = silence_timeout_s;
  last_sample_wall_s_ = wall_now_s;
  ended_silent_ = false;
  settling_ = settle;
  settle_until_s_ = kNaN;
  reason_.clear();
}

void StepAcquisition::Stop() {
  // Leaving a running record (q, b, s, the source ended): the chunk being filled is committed,
  // so only an unclean end loses it.
  if (record_ && !record_->complete()) record_->Flush();
  record_.reset();
  capture_.reset();
  quiet_.reset();
}

double StepAcquisition::quiet_progress() const {
  if (!quiet_ || quiet_->n < 2) return 0.0;
  const double by_time = (quiet_->t_last_s - quiet_->t_first_s) / quiet_period_s_;
  const double by_count = static_cast<double>(quiet_->n) / static_cast<double>(NoiseFloor::kMinQuietSamples);
  return std::min({1.0, by_time, by_count});
}

Capture StepAcquisition::TakeCapture() {
  Capture c = std::move(*accepted_);
  accepted_.reset();
  return c;
}

AcquisitionEvent StepAcquisition::Feed(const std::vector<Sample>& chunk, double wall_now_s) {
  if (chunk.empty()) return AcquisitionEvent::kNone;
  if (std::any_of(chunk.begin(), chunk.end(), [](const Sample& x) {
        return std::isfinite(x.t_s) && x.raw_counts.allFinite();
      }))
    last_sample_wall_s_ = wall_now_s;
  if (quiet_) return FeedQuiet(chunk);
  if (capture_) return FeedCapture(chunk);
  if (record_) return FeedRecord(chunk);
  return AcquisitionEvent::kNone;
}

AcquisitionEvent StepAcquisition::Watch(double wall_now_s) {
  const double silent_s = wall_now_s - last_sample_wall_s_;
  if (quiet_ && silent_s > timeout_s_) {
    reason_ = fmt::format("no samples for {:.0f} s: the noise floor cannot be measured", silent_s);
    quiet_.reset();
    return AcquisitionEvent::kNoiseFloorSilent;
  }
  if (record_ && silent_s > timeout_s_) return StopSilentRecord(silent_s);
  if (!capture_) return AcquisitionEvent::kNone;
  const bool capturing = capture_->Snapshot().state == CaptureState::kCapturing;
  const bool too_long = wall_now_s - capture_wall_start_s_ > timeout_s_ && !capturing;
  if (!(silent_s > timeout_s_) && !too_long) return AcquisitionEvent::kNone;
  const std::string problem = silent_s >= 1.0
                                  ? fmt::format("no samples for {:.0f} s", silent_s)
                                  : capture_->Snapshot().reason;
  ended_silent_ = silent_s >= 1.0;
  reason_ = fmt::format("no stable capture within {:.3g} s (wall clock): {}", timeout_s_,
                        problem.empty() ? "no data long enough to judge" : problem);
  capture_.reset();
  return AcquisitionEvent::kCaptureRejected;
}

// A record is never given up for what it records, but a link that sends nothing readable
// would keep it waiting forever: it is stopped (the chunk being filled committed, so the record
// holds every sample up to the last good one) and the wizard says why.
AcquisitionEvent StepAcquisition::StopSilentRecord(double silent_s) {
  const RecordView v = record_->View();
  reason_ = fmt::format("no samples for {:.0f} s: the record stopped at {} of {} (kept up to its "
                        "last sample)", silent_s, FormatLongDuration(v.recorded_s),
                        FormatLongDuration(v.duration_s));
  ended_silent_ = true;
  Stop();
  return AcquisitionEvent::kRecordSilent;
}

// The quiet period lasts quiet_period_s of the samples' clock and at least
// NoiseFloor::kMinQuietSamples samples: a slow stream (a vehicle before its rate request took,
// a link losing most frames) rests longer rather than giving a floor from a handful.
bool StepAcquisition::QuietDone() const {
  return quiet_->n >= NoiseFloor::kMinQuietSamples && quiet_->t_last_s - quiet_->t_first_s >= quiet_period_s_;
}

AcquisitionEvent StepAcquisition::FeedQuiet(const std::vector<Sample>& chunk) {
  for (const Sample& s : chunk) {
    quiet_->Add(s);
    quiet_samples_.push_back(s);
    if (QuietDone()) break;
  }
  if (!QuietDone()) return AcquisitionEvent::kNone;
  quiet_.reset();
  return AcquisitionEvent::kNoiseFloorMeasured;
}

AcquisitionEvent StepAcquisition::FeedCapture(const std::vector<Sample>& chunk) {
  capture_->Feed(chunk);
  const CaptureSnapshot snap = capture_->Snapshot();
  if (capture_->finished()) last_turntable_ = snap.turntable;
  switch (snap.state) {
    case CaptureState::kAccepted:
      accepted_ = capture_->capture();
      capture_.reset();
      return AcquisitionEvent::kCaptureAccepted;
    case CaptureState::kRejected:
    case CaptureState::kTimedOut:
      reason_ = snap.reason;
      capture_.reset();
      return AcquisitionEvent::kCaptureRejected;
    case CaptureState::kRetrying:
      reason_ = snap.reason;
      return AcquisitionEvent::kCaptureRetrying;
    case CaptureState::kCapturing:
      reason_.clear();
      return AcquisitionEvent::kCapturing;
    default:
      return AcquisitionEvent::kNone;
  }
}

AcquisitionEvent StepAcquisition::FeedRecord(const std::vector<Sample>& chunk) {
  std::vector<Sample> samples = chunk;
  if (settling_) {
    // The record starts kRecordSettleS after the first sample following the placement.
    if (std::isnan(settle_until_s_)) settle_until_s_ = chunk.front().t_s + kRecordSettleS;
    std::erase_if(samples, [&](const Sample& x) { return x.t_s < settle_until_s_; });
    if (samples.empty()) return AcquisitionEvent::kNone;
    settling_ = false;
  }
  record_->Feed(samples);
  return record_->complete() ? AcquisitionEvent::kRecordComplete : AcquisitionEvent::kNone;
}

}  // namespace accelcal

#include "accelcal/app/wizard/step_acquisition.h"

#include <algorithm>
#include <cmath>

namespace accelcal {

StepAcquisition::StepAcquisition(double quiet_period_s) : quiet_period_s_(quiet_period_s) {}

void StepAcquisition::MeasureNoiseFloor() {
  Stop();
  quiet_samples_.clear();
  quiet_ = CaptureStats();
}

void StepAcquisition::StartCapture(const CaptureRequest& request, const CaptureEngineOptions& options,
                                   const CaptureContext& context) {
  Stop();
  capture_ = std::make_unique<CaptureEngine>(request, options, context);
  reason_.clear();
}

void StepAcquisition::StartRecord(std::unique_ptr<RecordStepWriter> record, bool settle) {
  Stop();
  record_ = std::move(record);
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
  return std::min(1.0, (quiet_->t_last_s - quiet_->t_first_s) / quiet_period_s_);
}

Capture StepAcquisition::TakeCapture() {
  Capture c = std::move(*accepted_);
  accepted_.reset();
  return c;
}

AcquisitionEvent StepAcquisition::Feed(const std::vector<Sample>& chunk) {
  if (chunk.empty()) return AcquisitionEvent::kNone;
  if (quiet_) return FeedQuiet(chunk);
  if (capture_) return FeedCapture(chunk);
  if (record_) return FeedRecord(chunk);
  return AcquisitionEvent::kNone;
}

AcquisitionEvent StepAcquisition::FeedQuiet(const std::vector<Sample>& chunk) {
  for (const Sample& s : chunk) {
    quiet_->Add(s);
    quiet_samples_.push_back(s);
    if (quiet_->n >= 3 && quiet_->t_last_s - quiet_->t_first_s >= quiet_period_s_) break;
  }
  if (quiet_->n < 3 || !(quiet_->t_last_s - quiet_->t_first_s >= quiet_period_s_))
    return AcquisitionEvent::kNone;
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

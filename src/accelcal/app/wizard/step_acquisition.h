// Feeding the source's samples to what the wizard's current step acquires: the noise floor
// measured while the sensor rests, one capture (acquire/capture_engine), or a record streamed to
// the journal in chunks (record_step_writer.h). The wizard engine decides what to acquire and reacts
// to what Feed reports; this class holds no step logic and knows nothing of the procedure.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "accelcal/acquire/capture_engine/capture_engine.h"
#include "accelcal/acquire/capture_engine/noise_floor.h"
#include "accelcal/app/wizard/record_step_writer.h"
#include "accelcal/base/capture.h"

namespace accelcal {

enum class AcquisitionEvent {
  kNone,                // nothing to report (idle, or still filling)
  kNoiseFloorMeasured,  // the quiet period is over: quiet_samples() holds it
  kCapturing,           // the capture engine is capturing (the sensor is still)
  kCaptureRetrying,     // a capture was interrupted (a bump, settling); it retries by itself
  kCaptureRejected,     // rejected or timed out: reason() says why; the capture is over
  kCaptureAccepted,     // TakeCapture() hands it over
  kRecordComplete,      // the record covers its duration
  kNoiseFloorSilent,    // the quiet period had no sample for its timeout (Watch): reason() says
  kRecordSilent,        // the record had no sample for its silence limit (Watch): it is stopped,
                        // kept up to its last sample; reason() says
};

// The computer's monotonic clock (std::chrono::steady_clock), s: the wall clock of
// StepAcquisition::Watch.
double SteadyNowS();

class StepAcquisition {
 public:
  // `quiet_period_s`: how long the sensor rests for the noise floor, s (> 0) of the samples'
  // clock, and at least NoiseFloor::kMinQuietSamples samples (a slow stream rests longer).
  explicit StepAcquisition(double quiet_period_s);

  // Starts a quiet period for the noise floor (its samples: quiet_samples(), judged by the
  // wizard's NoiseFloorGuard); Watch ends it when no sample comes for timeout_s of wall time.
  void MeasureNoiseFloor(double wall_now_s, double timeout_s);
  // Starts a capture (judged against the context's noise floor).
  void StartCapture(const CaptureRequest& request, const CaptureEngineOptions& options,
                    const CaptureContext& context, double wall_now_s);
  // Starts streaming `record`; with `settle`, its first kRecordSettleS of samples are dropped
  // (the hand letting go of a freshly placed sensor). Watch stops it when no finite sample
  // comes for silence_timeout_s of wall time (> 0) from `wall_now_s` or the last one.
  void StartRecord(std::unique_ptr<RecordStepWriter> record, bool settle, double wall_now_s,
                   double silence_timeout_s);
  // Stops what runs: a record commits the chunk being filled; a capture in progress is dropped.
  void Stop();

  // `wall_now_s`: SteadyNowS(), for the wall-clock timeout of Watch.
  AcquisitionEvent Feed(const std::vector<Sample>& chunk, double wall_now_s);
  // The timeouts on the wall clock, called at every poll (data or not). The capture engine
  // counts its timeout in sample time, which stops when the link goes silent (connected,
  // sending nothing or only unreadable lines): a capture that is not capturing timeout_s of
  // wall time after it started, or that has had no finite sample for timeout_s, is over
  // (kCaptureRejected; reason() names the silence: "no stable capture within 20 s (wall
  // clock): no samples for 20 s"); a quiet period without a finite sample for its timeout_s is
  // over (kNoiseFloorSilent); a record without a finite sample for its silence limit is
  // stopped, kept up to its last sample (kRecordSilent; reason(): "no samples for 61 s: the
  // record stopped at 3 h 12 min of 12 h 0 min (kept up to its last sample)"). Nothing to do
  // otherwise (kNone).
  AcquisitionEvent Watch(double wall_now_s);

  bool measuring_noise_floor() const { return quiet_.has_value(); }
  bool capturing() const { return capture_ != nullptr; }
  bool recording() const { return record_ != nullptr; }
  bool record_settling() const { return record_ != nullptr && settling_; }

  // The last quiet period's samples (after kNoiseFloorMeasured).
  const std::vector<Sample>& quiet_samples() const { return quiet_samples_; }
  // Of the quiet period, 0..1.
  double quiet_progress() const;
  // The running capture's snapshot (capturing() must be true).
  CaptureSnapshot capture_snapshot() const { return capture_->Snapshot(); }
  // The running capture's give-up, its request's timeout_s (the settling wait included), s.
  double capture_timeout_s() const { return timeout_s_; }
  // Why the last capture was rejected or is retrying.
  const std::string& reason() const { return reason_; }
  // The last capture ended on the wall clock with no samples coming (Watch): a link problem.
  bool ended_silent() const { return ended_silent_; }
  // The turntable checks' verdict of the last capture that ended (accepted or rejected).
  const TurntableVerdict& last_turntable() const { return last_turntable_; }
  // The accepted capture (after kCaptureAccepted); the capture is over.
  Capture TakeCapture();
  // The running record (recording() must be true).
  const RecordStepWriter& record() const { return *record_; }

  // A fresh record starts this long after the sensor is placed (the hand letting go; the
  // simulator's placement moves for 1.5 s), s.
  static constexpr double kRecordSettleS = 2.0;

 private:
  AcquisitionEvent FeedQuiet(const std::vector<Sample>& chunk);
  bool QuietDone() const;
  AcquisitionEvent FeedCapture(const std::vector<Sample>& chunk);
  AcquisitionEvent FeedRecord(const std::vector<Sample>& chunk);
  AcquisitionEvent StopSilentRecord(double silent_s);

  double quiet_period_s_;
  std::optional<CaptureStats> quiet_;  // while measuring the noise floor
  std::vector<Sample> quiet_samples_;
  TurntableVerdict last_turntable_;
  std::unique_ptr<CaptureEngine> capture_;
  double timeout_s_ = kNaN;             // the capture's (request) or the quiet period's, s
  double capture_wall_start_s_ = kNaN;  // wall clock at StartCapture, s
  double last_sample_wall_s_ = kNaN;    // wall clock at the last finite sample (or the start), s
  std::optional<Capture> accepted_;
  std::unique_ptr<RecordStepWriter> record_;
  bool settling_ = false;
  double settle_until_s_ = kNaN;  // source t at which a settling record starts, s
  std::string reason_;
  bool ended_silent_ = false;
};

}  // namespace accelcal

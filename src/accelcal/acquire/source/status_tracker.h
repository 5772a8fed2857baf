// The bookkeeping every source shares: counts, the sample-rate estimate, gaps in t and the
// link state machine (connecting -> up <-> dead, -> ended). Sources report what they see
// (samples, malformed lines, link up or lost, end) with the wall time; the tracker keeps the
// SourceStatus and marks the ReadResult of the call in progress.
//
// Rate: the median of the last kRateWindow sample intervals (robust to a gap or a burst),
// refreshed every few samples. Gap: an interval above gap_factor times that median (only once
// the median is known). Dead: no sample for dead_after_s of wall time since the latest sample
// or since the link came up, whichever is later.
#pragma once

#include <array>
#include <string>

#include "accelcal/base/capture.h"
#include "accelcal/acquire/source/source_status.h"

namespace accelcal {

class StatusTracker {
 public:
  static constexpr int kRateWindow = 64;

  // now_s: wall time the source was created, s.
  StatusTracker(double gap_factor, double dead_after_s, double now_s);

  // Samples delivered in this call, in order, received at wall time now_s.
  void OnSamples(const Sample* samples, long count, double now_s, ReadResult* result);
  // `count` malformed lines; `last` is the latest one's complaint.
  void OnMalformed(long count, const std::string& last, ReadResult* result);
  // The link opened (first time or again).
  void OnLinkUp(double now_s, ReadResult* result);
  // The link failed; `why` says how (errno text). The state becomes dead.
  void OnLinkLost(const std::string& why, ReadResult* result);
  // An attempt to (re)open failed; the state stays as it is, the reason is kept.
  void OnOpenFailed(const std::string& why);
  // The source is finished.
  void OnEnded(ReadResult* result);
  // Updates the age of the latest sample and applies the dead-link rule. `silence`, when not
  // empty, says why nothing arrives ("no heartbeat from system 1 for 3.2 s"), beside the time.
  void Tick(double now_s, ReadResult* result, const std::string& silence = {});
  // A new reason for the silence (a vehicle's heartbeats stopped after its samples had): a
  // notice, and, when the link is dead for want of samples, its error says the new reason.
  void OnSilenceReason(const std::string& silence, double now_s, ReadResult* result);
  // Something the source noticed that is neither a sample nor an error (status().last_notice).
  void OnNotice(const std::string& notice, ReadResult* result,
                SourceNoticeKind kind = SourceNoticeKind::kOther);
  // The stream's unit and resolution, once the source knows them.
  void SetUnit(const ReadingUnit& unit, double resolution_counts);
  void SetLostFrames(long lost_frames) { status_.lost_frames = lost_frames; }

  const SourceStatus& status() const { return status_; }

 private:
  void AddInterval(double dt_s);
  void RefreshMedian();
  void BecomeUp(ReadResult* result);

  double gap_factor_;
  double dead_after_s_;
  SourceStatus status_;
  double quiet_since_s_;  // wall time from which silence counts towards dead, s
  bool dead_of_silence_ = false;  // dead for want of samples (not a connection error)
  double last_sample_wall_s_ = kNaN;
  std::array<double, kRateWindow> intervals_s_{};
  long intervals_seen_ = 0;
  long since_refresh_ = 0;
  double median_dt_s_ = kNaN;
};

}  // namespace accelcal

// The capture engine: what stands between a live stream of samples and a capture the fit can
// trust. One engine per requested capture (capture_request.h); it knows nothing of sources:
// feed it the chunks a source produces, read a snapshot for the UI, take the capture when
// accepted.
//
// States (time comes from the samples' t, never the wall clock, so a simulated bench may run
// faster than real time):
//
//   kSettling   waiting for the sensor to be still (static: a sliding window of
//               settle_window_s passes the static stability check) or the table to turn
//               steadily (turntable: the last turntable_settle_window_s pass the turntable
//               checks, the tilt aside: it is judged on the whole capture, which the hand's
//               shake of the mounting no longer reaches).
//               Then the pose is checked (static: orientation_check.h) and capturing begins.
//   kCapturing  collecting duration_s of samples; the stability check runs on the growing
//               capture every check_interval_s, so a bump restarts at once.
//   kRetrying   a check failed (reason in words); like kSettling, and capturing restarts by
//               itself when the sensor is still again. The failed samples are dropped. A
//               spike's reason follows the bump to its largest excursion (static_stability.h).
//   kAccepted   the capture passed screening (capture_screening.h: NaN, clipping, out of
//               range), stability and orientation (static) or the turntable checks, whose
//               once-per-revolution swing is then removed from the samples (the statistics
//               are of the swing-free samples; Snapshot().turntable.swing says what was
//               removed). Final.
//   kTimedOut   no capture accepted within timeout_s of the first sample (a capture already
//               running when the time is up may finish):
//               "no stable capture within 60 s: last problem: moving: x std 4.1 counts, limit 2.5"
//               Final (Restart() tries again).
//   kRejected   a problem waiting cannot fix: a NaN or clipped reading, the wrong face, a pose
//               already captured, a turntable mounted on the wrong axes or running other than
//               the entered rpm and radius, a tilted table, a plan beyond the sensor's range.
//               Final (Restart()).
//
// Memory: running sums and the settle window's samples (window x rate) while settling; the
// capture's own samples (duration x rate) while capturing.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/acquire/capture_engine/capture_request.h"
#include "accelcal/acquire/capture_engine/static_stability.h"
#include "accelcal/acquire/capture_engine/turntable_stability.h"
#include "accelcal/calibration/capture_screening.h"

namespace accelcal {

enum class CaptureState { kSettling, kCapturing, kRetrying, kAccepted, kTimedOut, kRejected };

// "settling", "capturing", "retrying", "accepted", "timed out", "rejected".
std::string_view CaptureStateToString(CaptureState state);

struct CaptureEngineOptions {
  StaticStabilityOptions stability;
  OrientationOptions orientation;
  TurntableStabilityOptions turntable;
  // NaN, clipping and out-of-range readings; give adc_range when known. Its min_samples is
  // checked on the finished capture.
  ScreeningOptions screening;
  // Static: the sensor must be still this long before capturing starts, s; > 0.
  double settle_window_s = 2.0;
  // Turntable: the run must be steady over this long before capturing starts, s; > 0.
  // Cover a few revolutions (6 at 120 rpm).
  double turntable_settle_window_s = 3.0;
  // How often (sample time) the stability is judged while settling and capturing, s; > 0.
  double check_interval_s = 0.05;
  // Same for the turntable check, which goes over its whole window, s; > 0.
  double turntable_check_interval_s = 0.25;

  std::string Validate() const;
};

// What a UI shows; a plain value (no references into the engine).
struct CaptureSnapshot {
  CaptureState state = CaptureState::kSettling;
  double progress = 0.0;  // 0..1 while capturing, 1 when accepted, else 0
  // Why the engine is not (yet) capturing or why it stopped, in words; empty when there is
  // nothing to say. kRetrying: the failed check; kSettling: the live problem.
  std::string reason;
  double elapsed_s = 0.0;   // sample time since the first sample fed, s
  int attempts = 0;         // captures started (1 + retries)
  // kSettling, static: still and in the right pose, waiting out the request's settle_wait_s:
  // what for and how long, in words ("...; waiting 12 s more"); empty otherwise.
  std::string settle_wait;
  StabilityVerdict stability;  // static: the live numbers of the window being judged
  TurntableVerdict turntable;  // turntable: the last verdict
};

class CaptureEngine {
 public:
  // Throws accelcal::Error when the request, options or context are not valid. A turntable
  // plan beyond the ADC range (when screening.adc_range is known) starts in kRejected.
  CaptureEngine(CaptureRequest request, const CaptureEngineOptions& options,
                CaptureContext context);

  void Feed(const std::vector<Sample>& chunk);
  void Feed(const Sample& sample);

  CaptureState state() const { return state_; }
  bool finished() const;
  CaptureSnapshot Snapshot() const;

  // The capture (kAccepted): id, kind, label, radius and rpm for a turntable, the samples.
  const Capture& capture() const { return capture_; }
  // Running statistics of the capture's samples (Welford).
  const CaptureStats& capture_stats() const { return stats_; }

  // Starts over after kTimedOut or kRejected (or at any time): a fresh timeout from the next
  // sample, nothing kept.
  void Restart();

 private:
  void Check(double t_s);
  void CheckSettledStatic(double t_s);
  void CheckSettledTurntable(double t_s);
  void CheckCapturing();
  void BeginCapture();
  void FinishCapture();
  void FinishStatic();
  // Checks the pose of a still reading; rejects the request (and returns true) when it is the
  // wrong face, out of tolerance or already captured.
  bool RejectedForPose(const Eigen::Vector3d& mean_counts);
  void FinishTurntable();
  void Retry(std::string reason);
  // Static: retries for the failed stability verdict live_, whose spike FollowSpike follows on.
  void RetryUnstable();
  void FollowSpike(const Sample& s);
  void Reject(std::string reason);
  bool CaptureComplete() const;
  void TrimTurntableWindow(double t_s);
  std::string LastProblem() const;

  CaptureRequest request_;
  CaptureEngineOptions options_;
  CaptureContext context_;

  CaptureState state_ = CaptureState::kSettling;
  std::string reason_;
  std::string settle_wait_;  // Snapshot().settle_wait
  int attempts_ = 0;
  double t_start_s_ = kNaN;       // first sample fed (since Restart)
  double t_last_s_ = kNaN;
  double t_next_check_s_ = kNaN;

  StaticStabilityMonitor settle_;        // static: sliding window
  StaticStabilityMonitor capture_monitor_;  // static: the capture so far
  std::vector<Sample> turntable_window_;    // turntable: the settle window's samples
  StabilityVerdict live_;
  StabilityVerdict retry_verdict_;  // static, kRetrying: the verdict that failed the capture
  TurntableVerdict turntable_verdict_;

  Capture capture_;
  CaptureStats stats_;
};

}  // namespace accelcal

// Is the sensor still? The static stability check of a window of samples, live (a sliding
// window while the operator sets the sensor down, a growing one while a capture runs) or
// offline (a whole capture of a set).
//
// Every limit is a multiple of the noise floor (noise_floor.h) on that axis,
//   sigma_i = max(floor_i, min_sigma_counts)        counts
// where the minimum stands in for the quantization of a nearly noise-free sensor. A window is
// stable when, on every axis i:
//   1. moving:   the window's std      <= std_multiplier   x sigma_i   (a hand on the table);
//   2. drifting: the trend over the window, |least-squares slope of x against t| x the window's
//                span, <= trend_multiplier x sigma_i (slow drift: warming up, a sagging mount);
//   3. spike:    no sample further than spike_sigmas x sigma_i from the mean of the samples
//                before it in the window (a bump, a door slammed); the readings of one bump
//                are one event, named by its largest excursion (SpikeEvent).
// Checks 1 and 2 need at least `min_samples` samples in the window (below that a window's std
// is too uncertain: 50 samples estimate a std within ~10 %); check 3 needs
// `min_spike_reference_samples` before the sample judged.
//
// Why these defaults: with the floor measured over a quiet period, a clean window of 100+
// samples has a std within ~7 % of the floor, so 1.5x is > 6 standard errors away; the trend
// a clean window shows by chance is sigma sqrt(12/n) (0.35 sigma at n = 100), so 2 sigma is
// > 5 standard errors; 6-sigma spikes occur by chance ~2e-9 per reading.
//
// Memory is bounded: running sums (detail/window_sums.h); a sliding window also keeps its own
// samples (window_s x rate of them) to take them out again, and at most kMaxSpikeEvents spikes.
//
// Units: counts for readings, s for times; the gauge ratios are dimensionless.
#pragma once

#include <deque>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/acquire/capture_engine/noise_floor.h"
#include "accelcal/acquire/window_sums.h"

namespace accelcal {

struct StaticStabilityOptions {
  // Std limit, in noise-floor sigmas; > 1. Raise it on a bench with vibration you accept.
  double std_multiplier = 1.5;
  // Trend limit over the window, in noise-floor sigmas; > 0.
  double trend_multiplier = 2.0;
  // Spike limit, in noise-floor sigmas; > 0.
  double spike_sigmas = 6.0;
  // Smallest sigma used, counts; >= 0. Keeps the limits sane for a noise-free, quantized
  // signal (rounding alone has a std of 0.29 counts).
  double min_sigma_counts = 0.67;
  // Samples a window needs before the std and trend are judged; >= 3.
  long min_samples = 50;
  // Samples before a reading that its spike check compares it with; >= 2.
  long min_spike_reference_samples = 10;

  std::string Validate() const;
};

// A spike event: readings that jumped away from the level before them (a bump, a door slammed).
// It begins at the first reading further than the spike limit from the mean of the window
// before it; that mean is the event's level, and every following reading that is a spike too
// and still beyond the limit from that level on the same axis belongs to the event (a bump rises
// over several readings: its first reading is only the rising edge). The event names its
// largest excursion from the level: its time and size. The first reading that is no spike ends
// it (a sensor moved to another level is not a bump that goes on).
struct SpikeEvent {
  int axis = 0;              // 0, 1, 2 = x, y, z
  double t_s = kNaN;         // time of the largest excursion, s
  double jump_counts = kNaN; // that reading minus the level, counts (signed)
  double sigmas = kNaN;      // |jump| / sigma_counts
  double level_counts = kNaN;  // the mean before the event on `axis`, counts
  double sigma_counts = kNaN;  // the sigma the excursions are measured in (the level's own
                               // uncertainty included), counts
  double t_first_s = kNaN;   // first reading of the event, s
  double t_last_s = kNaN;    // last reading of the event so far, s
  bool open = true;          // the last reading judged belonged to it (it may go on)
};

// Continues `event` with the next reading `s`: when `s` is still further than limit_sigmas x
// event->sigma_counts from the level on the event's axis, it belongs to the event (which keeps
// its largest excursion) and true is returned; else the event is closed (false). A closed event
// stays closed.
bool ContinueSpikeEvent(SpikeEvent* event, const Sample& s, double limit_sigmas);
// "spike: x jumped 138 counts (92.0 sigma) at t = 4.07 s"
std::string DescribeSpike(const SpikeEvent& e);

// The verdict on one window, with the numbers a UI needs for a "how still" gauge.
struct StabilityVerdict {
  // Enough samples to judge (min_samples). A window that is not judged is not stable.
  bool judged = false;
  bool stable = false;
  // Empty when stable; else every failed check in words, joined by "; ", e.g.
  // "moving: x std 4.1 counts, limit 2.5", "drifting: z moved 6.3 counts over the window,
  // limit 3.0", "spike: y jumped 41 counts (9.2 sigma) at t = 12.34 s", or, before enough
  // samples, "judging: 12 of 50 samples".
  std::string reason;

  long n_samples = 0;
  double span_s = kNaN;  // time from the window's first sample to its last, s
  Eigen::Vector3d mean_counts = Eigen::Vector3d::Constant(kNaN);
  Eigen::Vector3d std_counts = Eigen::Vector3d::Constant(kNaN);
  Eigen::Vector3d std_limit_counts = Eigen::Vector3d::Constant(kNaN);
  Eigen::Vector3d trend_counts = Eigen::Vector3d::Constant(kNaN);  // signed, over span_s
  Eigen::Vector3d trend_limit_counts = Eigen::Vector3d::Constant(kNaN);
  std::optional<SpikeEvent> largest_spike;  // the largest spike in the window, if any
  double spike_limit_sigmas = kNaN;

  // The reason from the numbers above (what Verdict() puts in `reason` when judged): a caller
  // that follows largest_spike on (ContinueSpikeEvent) words it again with this.
  std::string JudgedReason() const;

  // Gauge: std / limit per axis (0 = dead still, 1 = at the limit, > 1 fails); NaN unjudged.
  Eigen::Vector3d StdRatio() const;
  // |trend| / limit per axis.
  Eigen::Vector3d TrendRatio() const;
  // The worst of all ratios (the spike's sigmas over its limit included): one "how still"
  // number for a gauge, 0..1+; NaN when not judged.
  double WorstRatio() const;
};

// Stability of a window fed one sample at a time. Non-finite readings are ignored (screening
// reports them). Samples must come in time order.
class StaticStabilityMonitor {
 public:
  static constexpr size_t kMaxSpikeEvents = 64;
  static constexpr double kGrowing = std::numeric_limits<double>::infinity();

  // window_s: a sliding window of this length, s (> 0), or kGrowing: every sample since the
  // last Reset. The options and floor must be valid (Validate()); they are copied.
  StaticStabilityMonitor(const StaticStabilityOptions& options, const NoiseFloor& floor,
                         double window_s);

  void Add(const Sample& s);
  void Reset();

  // The verdict on the current window (formats the reason: not for every sample at 10 kHz).
  StabilityVerdict Verdict() const;

  long n() const { return sums_.n(); }
  // True when samples cover a whole window_s since the last Reset (always for kGrowing).
  bool full() const;
  Eigen::Vector3d mean_counts() const { return sums_.Mean(); }
  // The last reading added was a spike (beyond the limit from the mean before it).
  bool last_reading_spiked() const { return last_reading_spiked_; }

 private:
  void CheckSpike(const Sample& s);
  void DropOld(double t_now_s);
  void Resync();
  double SpanS() const;

  StaticStabilityOptions options_;
  Eigen::Vector3d sigma_counts_;  // max(floor, min_sigma_counts) per axis
  double window_s_;
  detail::WindowSums sums_;
  std::deque<Sample> ring_;  // sliding window only: its samples, oldest first
  std::deque<SpikeEvent> spikes_;  // the last one may be open (a bump still going on)
  long removals_since_resync_ = 0;
  bool last_reading_spiked_ = false;
  double t_reset_s_ = kNaN;  // first sample since Reset
  double t_first_s_ = kNaN;  // growing window: first sample
  double t_last_s_ = kNaN;
};

// The verdict on all finite samples of `samples` as one window (offline: a capture of a set).
// Throws accelcal::Error when options or floor are not valid.
StabilityVerdict EvaluateStaticStability(const std::vector<Sample>& samples,
                                         const NoiseFloor& floor,
                                         const StaticStabilityOptions& options);

}  // namespace accelcal

#include "accelcal/acquire/capture_engine/static_stability.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

constexpr char kAxisNames[3] = {'x', 'y', 'z'};
// Removals from a sliding window between rebuilds of its sums (rounding drift).
constexpr long kResyncRemovals = 4096;

int WorstAxis(const Eigen::Vector3d& ratio) {
  int worst = 0;
  for (int axis = 1; axis < 3; ++axis) {
    if (ratio[axis] > ratio[worst]) worst = axis;
  }
  return worst;
}

std::string MovingReason(const StabilityVerdict& v) {
  const int a = WorstAxis(v.StdRatio());
  return fmt::format("moving: {} std {:.2g} counts, limit {:.2g}", kAxisNames[a], v.std_counts[a],
                     v.std_limit_counts[a]);
}

std::string DriftingReason(const StabilityVerdict& v) {
  const int a = WorstAxis(v.TrendRatio());
  return fmt::format("drifting: {} moved {:.2g} counts over the window, limit {:.2g}",
                     kAxisNames[a], v.trend_counts[a], v.trend_limit_counts[a]);
}

}  // namespace

std::string DescribeSpike(const SpikeEvent& e) {
  return fmt::format("spike: {} jumped {:.3g} counts ({:.1f} sigma) at t = {:.2f} s",
                     kAxisNames[e.axis], e.jump_counts, e.sigmas, e.t_s);
}

bool ContinueSpikeEvent(SpikeEvent* e, const Sample& s, double limit_sigmas) {
  if (!e->open) return false;
  const double jump_counts = s.raw_counts[e->axis] - e->level_counts;
  const double sigmas = std::abs(jump_counts) / e->sigma_counts;
  if (!IsFinite(s) || !(sigmas > limit_sigmas)) {
    e->open = false;
    return false;
  }
  e->t_last_s = s.t_s;
  if (sigmas > e->sigmas) {
    e->t_s = s.t_s;
    e->jump_counts = jump_counts;
    e->sigmas = sigmas;
  }
  return true;
}

std::string StaticStabilityOptions::Validate() const {
  if (!(std::isfinite(std_multiplier) && std_multiplier > 1.0))
    return fmt::format("std_multiplier is {}, must be > 1", std_multiplier);
  if (!(std::isfinite(trend_multiplier) && trend_multiplier > 0.0))
    return fmt::format("trend_multiplier is {}, must be > 0", trend_multiplier);
  if (!(std::isfinite(spike_sigmas) && spike_sigmas > 0.0))
    return fmt::format("spike_sigmas is {}, must be > 0", spike_sigmas);
  if (!(std::isfinite(min_sigma_counts) && min_sigma_counts >= 0.0))
    return fmt::format("min_sigma_counts is {}, must be >= 0 counts", min_sigma_counts);
  if (min_samples < 3) return fmt::format("min_samples is {}, must be >= 3", min_samples);
  if (min_spike_reference_samples < 2)
    return fmt::format("min_spike_reference_samples is {}, must be >= 2",
                       min_spike_reference_samples);
  return {};
}

Eigen::Vector3d StabilityVerdict::StdRatio() const {
  return std_counts.cwiseQuotient(std_limit_counts);
}

Eigen::Vector3d StabilityVerdict::TrendRatio() const {
  return trend_counts.cwiseAbs().cwiseQuotient(trend_limit_counts);
}

double StabilityVerdict::WorstRatio() const {
  if (!judged) return kNaN;
  double worst = std::max(StdRatio().maxCoeff(), TrendRatio().maxCoeff());
  if (largest_spike) worst = std::max(worst, largest_spike->sigmas / spike_limit_sigmas);
  return worst;
}

StaticStabilityMonitor::StaticStabilityMonitor(const StaticStabilityOptions& options,
                                               const NoiseFloor& floor, double window_s)
    : options_(options),
      sigma_counts_(floor.std_counts.cwiseMax(options.min_sigma_counts)),
      window_s_(window_s) {}

void StaticStabilityMonitor::Reset() {
  last_reading_spiked_ = false;
  sums_ = detail::WindowSums{};
  ring_.clear();
  spikes_.clear();
  removals_since_resync_ = 0;
  t_reset_s_ = t_first_s_ = t_last_s_ = kNaN;
}

void StaticStabilityMonitor::Add(const Sample& s) {
  if (!IsFinite(s)) return;
  if (sums_.n() == 0 && ring_.empty()) {
    sums_.Reset(s.raw_counts, s.t_s);
    if (std::isnan(t_reset_s_)) t_reset_s_ = s.t_s;
    t_first_s_ = s.t_s;
  }
  CheckSpike(s);  // against the window before this reading
  sums_.Add(s.raw_counts, s.t_s);
  t_last_s_ = s.t_s;
  if (window_s_ != kGrowing) {
    ring_.push_back(s);
    DropOld(s.t_s);
  }
}

void StaticStabilityMonitor::CheckSpike(const Sample& s) {
  last_reading_spiked_ = false;
  if (sums_.n() < options_.min_spike_reference_samples) return;
  const Eigen::Vector3d jump = s.raw_counts - sums_.Mean();
  // The mean of n readings is itself uncertain by sigma / sqrt(n).
  const double inflate = std::sqrt(1.0 + 1.0 / static_cast<double>(sums_.n()));
  const Eigen::Vector3d sigmas = jump.cwiseAbs().cwiseQuotient(sigma_counts_ * inflate);
  const int axis = WorstAxis(sigmas);
  if (!(sigmas[axis] > options_.spike_sigmas)) {
    if (!spikes_.empty()) spikes_.back().open = false;
    return;
  }
  // Which readings are spikes is decided as it always was (against the mean before each); a
  // spike right after one of the same bump (still beyond the limit from the level before the
  // bump) joins its event, which then names the bump's largest excursion from that level. So
  // the verdicts are those of one event per reading; only the naming changes.
  last_reading_spiked_ = true;
  if (!spikes_.empty() && ContinueSpikeEvent(&spikes_.back(), s, options_.spike_sigmas)) return;
  if (spikes_.size() == kMaxSpikeEvents) spikes_.pop_front();
  SpikeEvent e;
  e.axis = axis;
  e.t_s = e.t_first_s = e.t_last_s = s.t_s;
  e.jump_counts = jump[axis];
  e.sigmas = sigmas[axis];
  e.level_counts = sums_.Mean()[axis];
  e.sigma_counts = sigma_counts_[axis] * inflate;
  spikes_.push_back(e);
}

// Takes out of a sliding window the samples (and spikes) older than window_s.
void StaticStabilityMonitor::DropOld(double t_now_s) {
  const double t_start_s = t_now_s - window_s_;
  while (!ring_.empty() && ring_.front().t_s < t_start_s) {
    sums_.Remove(ring_.front().raw_counts, ring_.front().t_s);
    ring_.pop_front();
    ++removals_since_resync_;
  }
  // An event leaves with its last reading (as each of its readings would on its own).
  while (!spikes_.empty() && spikes_.front().t_last_s < t_start_s) spikes_.pop_front();
  if (removals_since_resync_ >= kResyncRemovals) Resync();
}

void StaticStabilityMonitor::Resync() {
  removals_since_resync_ = 0;
  if (ring_.empty()) return;
  sums_.Reset(ring_.front().raw_counts, ring_.front().t_s);
  for (const Sample& s : ring_) sums_.Add(s.raw_counts, s.t_s);
}

double StaticStabilityMonitor::SpanS() const {
  if (sums_.n() == 0) return kNaN;
  const double t_first_s = window_s_ == kGrowing ? t_first_s_ : ring_.front().t_s;
  return t_last_s_ - t_first_s;
}

bool StaticStabilityMonitor::full() const {
  if (window_s_ == kGrowing) return true;
  if (sums_.n() < 2) return false;
  // Readings come every dt: a window of window_s holds readings spanning window_s - dt.
  const double dt_s = SpanS() / static_cast<double>(sums_.n() - 1);
  return t_last_s_ - t_reset_s_ + dt_s >= window_s_ * (1.0 - 1e-9);
}

StabilityVerdict StaticStabilityMonitor::Verdict() const {
  StabilityVerdict v;
  v.n_samples = sums_.n();
  v.span_s = SpanS();
  v.mean_counts = sums_.Mean();
  v.spike_limit_sigmas = options_.spike_sigmas;
  v.std_limit_counts = options_.std_multiplier * sigma_counts_;
  v.trend_limit_counts = options_.trend_multiplier * sigma_counts_;
  if (v.n_samples < options_.min_samples) {
    v.reason = fmt::format("judging: {} of {} samples", v.n_samples, options_.min_samples);
    return v;
  }
  v.judged = true;
  v.std_counts = sums_.Variance().cwiseSqrt();
  v.trend_counts = sums_.SlopePerS() * v.span_s;
  if (!v.trend_counts.allFinite()) v.trend_counts.setZero();  // all samples at one t
  for (const SpikeEvent& e : spikes_) {
    if (!v.largest_spike || e.sigmas > v.largest_spike->sigmas) v.largest_spike = e;
  }
  v.reason = v.JudgedReason();
  v.stable = v.reason.empty();
  return v;
}

std::string StabilityVerdict::JudgedReason() const {
  std::vector<std::string> failures;
  if ((StdRatio().array() > 1.0).any()) failures.push_back(MovingReason(*this));
  if ((TrendRatio().array() > 1.0).any()) failures.push_back(DriftingReason(*this));
  if (largest_spike) failures.push_back(DescribeSpike(*largest_spike));
  return fmt::format("{}", fmt::join(failures, "; "));
}

StabilityVerdict EvaluateStaticStability(const std::vector<Sample>& samples,
                                         const NoiseFloor& floor,
                                         const StaticStabilityOptions& options) {
  if (std::string e = options.Validate(); !e.empty()) throw Error("stability options: " + e);
  if (std::string e = floor.Validate(); !e.empty()) throw Error("stability: " + e);
  StaticStabilityMonitor monitor(options, floor, StaticStabilityMonitor::kGrowing);
  for (const Sample& s : samples) monitor.Add(s);
  return monitor.Verdict();
}

}  // namespace accelcal

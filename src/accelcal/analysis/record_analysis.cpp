#include "accelcal/analysis/record_analysis.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {

std::string RecordAnalysisOptions::Validate() const {
  if (!std::isnan(rate_hz) && !(rate_hz > 0.0 && std::isfinite(rate_hz)))
    return "rate_hz must be > 0 (or NaN: estimated)";
  if (rate_probe_samples < 3) return "rate_probe_samples must be >= 3";
  if (!(gap_factor > 1.0) || !std::isfinite(gap_factor)) return "gap_factor must be > 1";
  if (!(max_gap_s > 0.0)) return "max_gap_s must be > 0";
  AllanOptions a = allan;
  a.tau0_s = 1.0;  // set from the rate later
  if (std::string p = a.Validate(); !p.empty()) return "allan: " + p;
  if (std::string p = drift.Validate(); !p.empty()) return "drift: " + p;
  return {};
}

RecordAnalyzer::RecordAnalyzer(const RecordAnalysisOptions& options, std::string unit)
    : options_(options),
      unit_(std::move(unit)),
      drift_{DriftTracker(options.drift), DriftTracker(options.drift), DriftTracker(options.drift)} {
  if (std::string p = options.Validate(); !p.empty()) throw Error("record analysis: " + p);
  if (unit_.empty()) throw Error("record analysis: the values' unit must be named");
  if (!std::isnan(options_.rate_hz)) Start(options_.rate_hz, false);
}

void RecordAnalyzer::Start(double rate_hz, bool estimated) {
  rate_hz_ = rate_hz;
  rate_estimated_ = estimated;
  AllanOptions allan = options_.allan;
  allan.tau0_s = 1.0 / rate_hz;
  for (int axis = 0; axis < 3; ++axis) allan_.emplace_back(allan);
  started_ = true;
  // Replay what the probe held; t_last_s_ restarts so the gaps among them are seen.
  std::vector<Pending> held;
  held.swap(probe_);
  t_last_s_ = kNaN;
  for (const Pending& p : held) Feed(p.t_s, p.value, p.temp_c);
}

void RecordAnalyzer::FlushAllan() {
  for (size_t axis = 0; axis < 3; ++axis) {
    allan_[axis].Add(std::span<const double>(pending_[axis]));
    pending_[axis].clear();
  }
}

void RecordAnalyzer::Add(double t_s, const Eigen::Vector3d& value, double temp_c) {
  if (!std::isfinite(t_s) || !value.allFinite() || std::isinf(temp_c))
    throw Error(fmt::format("record analysis: sample at t = {} s has a value that is not a finite "
                            "number ({}, {}, {}; temperature {})",
                            t_s, value.x(), value.y(), value.z(), temp_c));
  if (!std::isnan(t_last_s_) && !(t_s > t_last_s_))
    throw Error(fmt::format("record analysis: t = {} s does not come after {} s", t_s, t_last_s_));
  if (!std::isnan(t_last_s_) && t_s - t_last_s_ > options_.max_gap_s)
    throw Error(fmt::format("record analysis: the clock jumps {} s (from {} to {} s): longer than "
                            "any pause of a record ({} s); is it the same record?",
                            t_s - t_last_s_, t_last_s_, t_s, options_.max_gap_s));
  ++received_;
  if (std::isnan(t_first_s_)) t_first_s_ = t_s;
  if (!started_) {
    probe_.push_back({t_s, value, temp_c});
    t_last_s_ = t_s;
    if (static_cast<int>(probe_.size()) >= options_.rate_probe_samples) StartFromProbe();
    return;
  }
  Feed(t_s, value, temp_c);
}

void RecordAnalyzer::Feed(double t_s, const Eigen::Vector3d& value, double temp_c) {
  if (!std::isnan(t_last_s_)) {
    const double step_s = t_s - t_last_s_;
    if (step_s * rate_hz_ > options_.gap_factor) {
      const auto missing = static_cast<std::int64_t>(std::llround(step_s * rate_hz_)) - 1;
      if (missing > 0) {
        gaps_.push_back({t_last_s_, t_s, missing});
        FlushAllan();
        for (AllanAccumulator& a : allan_) a.AddMissing(missing);
      }
    }
  }
  // The three trackers share the record's times: the window number is found once.
  const std::int64_t window = drift_[0].WindowOf(t_s);
  for (int axis = 0; axis < 3; ++axis) {
    pending_[static_cast<size_t>(axis)].push_back(value[axis]);
    drift_[static_cast<size_t>(axis)].AddInWindow(window, t_s, value[axis], temp_c);
  }
  if (pending_[0].size() >= kBatch) FlushAllan();
  if (!std::isnan(temp_c)) has_temperature_ = true;
  t_last_s_ = t_s;
}

void RecordAnalyzer::StartFromProbe() {
  // The median interval: a few gaps or late samples among the first do not move it.
  std::vector<double> steps;
  for (size_t i = 1; i < probe_.size(); ++i) steps.push_back(probe_[i].t_s - probe_[i - 1].t_s);
  std::nth_element(steps.begin(), steps.begin() + static_cast<long>(steps.size() / 2), steps.end());
  // Time stamps printed with few digits make the interval inexact (0.0200000000000004 s):
  // six significant digits of the rate are all the stamps can tell.
  const double rate_hz = 1.0 / steps[steps.size() / 2];
  const double digit = std::pow(10.0, std::floor(std::log10(rate_hz)) - 5);
  Start(std::round(rate_hz / digit) * digit, true);
}

RecordAnalysis RecordAnalyzer::Result() {
  if (!started_ && probe_.size() >= 2) StartFromProbe();
  RecordAnalysis r;
  r.unit = unit_;
  r.rate_hz = rate_hz_;
  r.rate_estimated = rate_estimated_;
  r.samples = received_;
  r.t_first_s = t_first_s_;
  r.t_last_s = t_last_s_;
  r.gaps = gaps_;
  r.has_temperature = has_temperature_;
  if (started_) FlushAllan();
  for (int axis = 0; axis < 3 && started_; ++axis) {
    AxisAnalysis& out = r.axes[static_cast<size_t>(axis)];
    out.curve = allan_[static_cast<size_t>(axis)].Curve();
    out.drift = drift_[static_cast<size_t>(axis)].Result();
    r.missing_samples = out.curve.missing_samples;
    if (out.curve.points.size() < 3) continue;
    std::vector<double> tau, adev, edf;
    for (const AllanPoint& p : out.curve.points) {
      if (!(p.adev > 0.0)) continue;  // a constant axis (e.g. a stuck reading) has no curve
      tau.push_back(p.tau_s);
      adev.push_back(p.adev);
      edf.push_back(std::isfinite(p.edf) && p.edf > 0 ? p.edf : 1.0);
    }
    if (tau.size() >= 3) out.read_offs = ReadOffAllan(tau, adev, edf);
  }
  return r;
}

}  // namespace accelcal

#include "accelcal/analysis/drift_stats.h"

#include <algorithm>
#include <cmath>

#include "accelcal/base/error.h"

namespace accelcal {

std::string DriftOptions::Validate() const {
  if (!(window_s > 0.0) || !std::isfinite(window_s)) return "window_s must be > 0";
  if (!(min_fill > 0.0 && min_fill <= 1.0)) return "min_fill must be in (0, 1]";
  return {};
}

DriftTracker::DriftTracker(const DriftOptions& options) : options_(options) {
  const std::string problem = options.Validate();
  if (!problem.empty()) throw Error("drift options: " + problem);
}

bool DriftTracker::Counts(const Window& w) const {
  return w.n > 0 &&
         w.t_last_s - w.t_first_s >= options_.min_fill * options_.window_s * (1.0 - 1e-9);
}

void DriftTracker::Close(const Window& w, Totals* t) {
  const double mean = w.sum / static_cast<double>(w.n);
  if (t->windows == 0) {
    t->first_mean = t->min_mean = t->max_mean = mean;
  } else {
    t->min_mean = std::min(t->min_mean, mean);
    t->max_mean = std::max(t->max_mean, mean);
  }
  ++t->windows;
  if (w.n_temp == 0) return;
  const double temp = w.sum_temp_c / static_cast<double>(w.n_temp);
  if (t->paired == 0) {
    // Sums about the first pair keep the centred sums below exact even for a bias of
    // thousands of counts that moves by a fraction of one.
    t->shift_t = temp;
    t->shift_v = mean;
    t->temp_min_c = t->temp_max_c = temp;
  }
  t->temp_min_c = std::min(t->temp_min_c, temp);
  t->temp_max_c = std::max(t->temp_max_c, temp);
  ++t->paired;
  const double dt = temp - t->shift_t;
  const double dv = mean - t->shift_v;
  t->sum_t += dt;
  t->sum_v += dv;
  t->sum_tt += dt * dt;
  t->sum_vv += dv * dv;
  t->sum_tv += dt * dv;
}

void DriftTracker::Add(double t_s, double value, double temp_c) {
  AddInWindow(WindowOf(t_s), t_s, value, temp_c);
}

std::int64_t DriftTracker::WindowOf(double t_s) {
  if (std::isnan(t0_s_)) t0_s_ = t_s;
  const double windows = (t_s - t0_s_) / options_.window_s;
  // The conversion truncates, which is the floor from t0 on (the common case: no call to floor).
  return static_cast<std::int64_t>(windows >= 0.0 ? windows : std::floor(windows));
}

void DriftTracker::AddInWindow(std::int64_t index, double t_s, double value, double temp_c) {
  if (index != current_.index) {
    if (Counts(current_)) Close(current_, &totals_);
    current_ = Window{};
    current_.index = index;
    current_.t_first_s = t_s;
  }
  ++current_.n;
  current_.sum += value;
  current_.t_last_s = t_s;
  if (!std::isnan(temp_c)) {
    ++current_.n_temp;
    current_.sum_temp_c += temp_c;
  }
}

DriftStats DriftTracker::Result() const {
  Totals t = totals_;
  if (Counts(current_)) Close(current_, &t);
  DriftStats s;
  s.windows = t.windows;
  s.first_mean = t.first_mean;
  s.min_mean = t.min_mean;
  s.max_mean = t.max_mean;
  if (t.windows > 0) s.max_drift = t.max_mean - t.min_mean;
  s.temp_min_c = t.temp_min_c;
  s.temp_max_c = t.temp_max_c;
  if (t.paired >= 3) {
    // Centred sums; the temperature must have moved for a slope to mean anything.
    const double n = static_cast<double>(t.paired);
    const double stt = t.sum_tt - t.sum_t * t.sum_t / n;
    const double svv = t.sum_vv - t.sum_v * t.sum_v / n;
    const double stv = t.sum_tv - t.sum_t * t.sum_v / n;
    if (stt > 1e-12) {  // degC^2: the temperature moved
      s.temp_slope_per_c = stv / stt;
      if (svv > 0.0) s.temp_correlation = stv / std::sqrt(stt * svv);
    }
  }
  return s;
}

}  // namespace accelcal

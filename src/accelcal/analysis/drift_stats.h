// The slow drift of a static record, in window means: the record is cut into consecutive windows
// of `window_s` (1 minute by default, the "1-minute means") on its own clock, each
// window's mean is taken, and the figures are
//   max_drift   peak to peak of the window means (the largest excursion of the bias over the
//               record), in the series' unit;
//   temperature correlation of the window means with the window mean temperatures (Pearson r)
//               and the least-squares slope, unit per degC, when the record carries temperature.
// Streaming: a bounded state (running sums over windows), whatever the record's length.
#pragma once

#include <cstdint>
#include <string>

#include "accelcal/base/capture.h"  // kNaN

namespace accelcal {

struct DriftOptions {
  double window_s = 60.0;  // length of a window, s; > 0
  // A window counts only when its samples span at least this fraction of it (a window cut by
  // the end of the record or by a gap says little about the bias); in (0, 1].
  double min_fill = 0.5;

  std::string Validate() const;  // empty when valid
};

struct DriftStats {
  std::int64_t windows = 0;      // windows counted
  double first_mean = kNaN;      // mean of the first counted window, series unit
  double min_mean = kNaN;        // smallest and largest window mean, series unit
  double max_mean = kNaN;
  double max_drift = kNaN;       // max_mean - min_mean, series unit; NaN with no window
  // With temperature (NaN otherwise, or with fewer than 3 windows or no temperature change):
  double temp_min_c = kNaN;      // range of the window mean temperatures, degC
  double temp_max_c = kNaN;
  double temp_correlation = kNaN;     // Pearson r of window means against temperature
  double temp_slope_per_c = kNaN;     // least-squares slope, series unit per degC
};

class DriftTracker {
 public:
  // Throws accelcal::Error for invalid options.
  explicit DriftTracker(const DriftOptions& options = {});

  // One reading `value` at time `t_s` (non-decreasing), with the temperature `temp_c` (NaN when
  // the record has none). Non-finite values are the caller's to refuse.
  void Add(double t_s, double value, double temp_c);
  // Add in two steps, for a caller with trackers of the same times (one per axis): the window
  // number of `t_s` (the first call fixes the record's start: call it for every sample, in
  // order), computed once for all of them, then the reading into that window.
  std::int64_t WindowOf(double t_s);
  void AddInWindow(std::int64_t window, double t_s, double value, double temp_c);

  // The figures so far (the window in progress is included when it is full enough).
  DriftStats Result() const;

 private:
  struct Window {
    std::int64_t index = -1;   // window number since the record's first sample
    std::int64_t n = 0;
    double sum = 0.0;
    std::int64_t n_temp = 0;
    double sum_temp_c = 0.0;
    double t_first_s = kNaN;
    double t_last_s = kNaN;
  };
  struct Totals {  // over counted windows
    std::int64_t windows = 0;
    double first_mean = kNaN;
    double min_mean = kNaN;
    double max_mean = kNaN;
    std::int64_t paired = 0;  // windows with a temperature
    double shift_t = 0, shift_v = 0;  // the first pair; the sums are of deviations from it
    double sum_t = 0, sum_v = 0, sum_tt = 0, sum_vv = 0, sum_tv = 0;
    double temp_min_c = kNaN;
    double temp_max_c = kNaN;
  };
  bool Counts(const Window& w) const;
  static void Close(const Window& w, Totals* totals);

  DriftOptions options_;
  double t0_s_ = kNaN;
  Window current_;
  Totals totals_;
};

}  // namespace accelcal

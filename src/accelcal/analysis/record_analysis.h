// The noise and drift analysis of a long static record (the drift procedure's 12 hours, or any
// recording): per axis, the overlapping Allan deviation with its confidence band
// (allan_deviation.h), the IEEE 952 read-offs (allan_readoffs.h) and the drift of 1-minute means
// with its temperature correlation (drift_stats.h). Streamed: a bounded state whatever the
// record's length, and Result() may be asked at any time for a live view.
//
// Units: the values given to Add are in the analyzer's `unit` ("counts" for raw readings,
// "m/s^2" once a calibration has been applied by the caller); every figure is in that unit
// (noise density unit/sqrt(Hz), random walk unit/sqrt(s)).
//
// Time and gaps: samples carry t (s, strictly increasing). The sample interval is the stated
// rate's, or the median of the first intervals. A step in t longer than gap_factor intervals is a
// gap of round(step / interval) - 1 missing readings: listed in the result, and no Allan term
// spans it. A step longer than max_gap_s is refused (a clock jump, not a pause).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/analysis/allan_deviation.h"
#include "accelcal/analysis/allan_readoffs.h"
#include "accelcal/analysis/drift_stats.h"
#include "accelcal/base/capture.h"

namespace accelcal {

struct RecordAnalysisOptions {
  // Sample rate, Hz; NaN: the median interval of the first rate_probe_samples samples.
  double rate_hz = kNaN;
  int rate_probe_samples = 1000;  // >= 3
  // A step in t longer than this many sample intervals is a gap (> 1).
  double gap_factor = 1.5;
  // A step in t longer than this is refused as a clock jump, s (> 0). A week.
  double max_gap_s = 7 * 86400.0;
  // The Allan deviation's options; tau0_s is set from the rate (its value here is ignored).
  // max_alpha 0: an accelerometer's readings hold no phase-type (alpha > 0) noise at the taus
  // where it would matter, and a chance "flicker PM" call would make a point's bounds ~3 times
  // too narrow (allan_deviation.h, AllanOptions::max_alpha).
  AllanOptions allan = [] {
    AllanOptions a;
    a.max_alpha = 0;
    return a;
  }();
  DriftOptions drift;

  std::string Validate() const;  // empty when valid
};

struct RecordAnalysisGap {
  double t_before_s = kNaN;        // last sample before the gap, s
  double t_after_s = kNaN;         // first sample after it, s
  std::int64_t missing_samples = 0;
};

struct AxisAnalysis {
  AllanCurve curve;
  std::optional<AllanReadOffs> read_offs;  // absent while the curve has fewer than 3 points
  DriftStats drift;
};

struct RecordAnalysis {
  std::string unit;                // of the values: "counts" or "m/s^2"
  double rate_hz = kNaN;           // sample rate used
  bool rate_estimated = false;     // from the samples' t rather than stated
  std::int64_t samples = 0;        // readings received
  std::int64_t missing_samples = 0;
  double t_first_s = kNaN;
  double t_last_s = kNaN;
  std::vector<RecordAnalysisGap> gaps;
  bool has_temperature = false;
  std::array<AxisAnalysis, 3> axes;  // x, y, z
};

class RecordAnalyzer {
 public:
  // Throws accelcal::Error for invalid options or an empty unit.
  RecordAnalyzer(const RecordAnalysisOptions& options, std::string unit);

  // One sample: its time, the three axes' values in the analyzer's unit, and temp_c (NaN when
  // absent). Throws accelcal::Error for a non-finite value, a t that does not increase, or a
  // clock jump; the samples before stay analysed.
  void Add(double t_s, const Eigen::Vector3d& value, double temp_c);

  // The analysis so far. With the rate still being estimated, the samples probed so far fix it
  // (at least 2 needed; before that the result holds no curve).
  RecordAnalysis Result();

 private:
  struct Pending {
    double t_s;
    Eigen::Vector3d value;
    double temp_c;
  };
  void Start(double rate_hz, bool estimated);
  void StartFromProbe();  // the rate from the probed samples' median interval
  void Feed(double t_s, const Eigen::Vector3d& value, double temp_c);

  RecordAnalysisOptions options_;
  std::string unit_;
  std::vector<Pending> probe_;  // samples held until the rate is known
  bool started_ = false;
  bool rate_estimated_ = false;
  double rate_hz_ = kNaN;
  double t_first_s_ = kNaN;
  double t_last_s_ = kNaN;
  std::int64_t received_ = 0;
  bool has_temperature_ = false;
  std::vector<RecordAnalysisGap> gaps_;
  void FlushAllan();  // hands the pending readings to the accumulators

  // Readings go to the accumulators in batches (their batch Add is several times faster).
  static constexpr size_t kBatch = 4096;
  std::array<std::vector<double>, 3> pending_;
  std::vector<AllanAccumulator> allan_;  // x, y, z once started
  std::array<DriftTracker, 3> drift_;
};

}  // namespace accelcal

// When a capture has enough data: the adaptive stop of a capture, decided by a sample count
// fixed before the capture starts, never by the data it collects.
//
// Why a count: the planner (capture_plan.h) says how many samples each capture needs for the
// target, from the noise floor measured at the start of the session. Stopping instead when the
// running mean "looks settled" (its own standard error, or its change, below a threshold) is
// optional stopping: the stop then depends on the noise realised, a capture that happened to
// fluctuate little stops early, and the mean and its stated uncertainty are biased (the
// coverage of the certificate's U falls). A count fixed in advance keeps every sample count
// independent of the samples, so the mean is the same unbiased mean a fixed-length capture
// gives.
//
// The count is bounded: at least the minimum (settling is the capture engine's, before the
// count starts; a turntable run is rounded up to whole revolutions, so its once-per-revolution
// swing averages out of the mean) and at most the procedure's maximum.
//
// Units: samples, s, rpm, Hz.
#pragma once

namespace accelcal {

struct CaptureStopRule {
  long needed_samples = 0;   // what the plan asks for, within [min, max]
  long min_samples = 1;
  long max_samples = 1;

  // The rule for a capture the plan gives `planned_s` seconds at `rate_hz`, at least
  // `min_capture_s`, at most `max_capture_s`; for a turntable run at `rpm` > 0, a whole number of
  // revolutions (the maximum rounded down to whole revolutions too, when one fits).
  static CaptureStopRule For(double planned_s, double rate_hz, double min_capture_s,
                             double max_capture_s, double rpm = 0.0);

  // The capture has enough with `samples` samples counted.
  bool Enough(long samples) const { return samples >= needed_samples; }
  // 0..1: the bar filling toward "enough".
  double Progress(long samples) const;
  // Seconds still to capture at `rate_hz`.
  double RemainingS(long samples, double rate_hz) const;
};

}  // namespace accelcal

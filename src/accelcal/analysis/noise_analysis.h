// The inherent-noise analysis (procedures/noise.toml): static records with z vertical, one per
// day. Per record and axis: mean, standard deviation, noise density over the flat part of the
// Welch PSD (welch_psd.h), the spectrum for plots, and a normality check (normality.h); across
// the records, the day-to-day change of the mean (turn-on bias repeatability).
//
// Units: counts, or m/s^2 (platform frame, a^p of sensor_model.h) when a calibration is given
// (each reading converted by CalibrationApplier first); NoiseReport::unit names which. Densities
// are in unit/sqrt(Hz), PSDs in unit^2/Hz (one-sided), frequencies in Hz.
//
// Noise density convention: the white-noise coefficient N of IEEE Std 952 (the Allan
// deviation's slope -1/2 line at 1 s, allan_readoffs.h) and of Kalibr's noise_density, so both
// analyses give the same number: white noise of per-sample std s at rate fs has N = s/sqrt(fs)
// and a one-sided PSD of 2 N^2. (A datasheet's "noise density" is usually the one-sided
// sqrt(PSD), sqrt(2) times larger.)
//
// Flat band: white noise is flat in the PSD, flicker and drift rise at low frequency, and the
// sensor's anti-alias filter rolls off near Nyquist. The band is [max(low_fraction * Nyquist,
// 4 * resolution), high_fraction * Nyquist] (by default 0.1 to 0.8 of Nyquist: 5 to 40 Hz at
// 100 Hz), and the density is sqrt of half the MEAN PSD over its bins (the mean of Welch estimates
// is unbiased for white noise; a median of chi-square-distributed estimates is biased low).
//
// Day-to-day: records are grouped by their UTC date; the first record of each day counts
// (later ones of the same day are left out, with a warning), records without a date are taken
// as days of their own (with a warning). With fewer than min_days days the figures are still
// given when there are two, with a warning; with one, they are NaN.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/analysis/normality.h"
#include "accelcal/analysis/welch_psd.h"
#include "accelcal/base/capture.h"
#include "accelcal/calibration/calibration.h"

namespace accelcal::analysis {

struct NoiseRecord {
  std::string label;  // where it came from: a session's name, a file's path
  std::string date;   // UTC day it was taken, "YYYY-MM-DD"; empty when unknown
  std::vector<Sample> samples;  // raw counts, t strictly increasing
};

// A record as the analysis reads it: `replay` calls its argument with the record's samples in
// order, a piece at a time, and gives the same samples every time it is called (the analysis
// reads a record three times, at most six: the median interval, the means, then the moments
// and the spectrum). Only a piece and one Welch segment per axis (at most 3 x 65 536 values)
// are in memory at a time: a record of any length is analysed in bounded memory.
using SamplePieceSink = std::function<void(const Sample* samples, std::size_t count)>;
struct NoiseRecordSource {
  std::string label;
  std::string date;
  std::function<void(const SamplePieceSink&)> replay;
};

// A source replaying `record`'s samples (which must outlive it) as one piece.
NoiseRecordSource ReplayOf(const NoiseRecord& record);
// A source that holds `samples` itself (a record that cannot be read again: a pipe, a capture
// kept whole by an old session), replayed as one piece.
NoiseRecordSource HeldRecord(std::string label, std::string date, std::vector<Sample> samples);

struct NoiseAnalysisOptions {
  double band_low_fraction = 0.1;   // flat band's low edge, fraction of Nyquist (also >= 4 bins)
  double band_high_fraction = 0.8;  // flat band's high edge, fraction of Nyquist
  int max_spectrum_points = 200;    // the plotted spectrum: at most this many log-spaced points
  double normality_alpha = 0.01;    // Jarque-Bera significance level
  double quantization_limit_counts = 1.0;  // below this std (counts) normality is not tested
  int min_days = 3;                 // days the repeatability figure asks for
  WelchOptions welch;

  // Empty when valid, else the problem.
  std::string Validate() const;
};

struct AxisNoise {
  double mean = kNaN;            // unit
  double std = kNaN;             // sample standard deviation (n - 1), unit
  double std_counts = kNaN;      // the same in raw counts (for the quantization rule)
  double density = kNaN;         // noise density, unit/sqrt(Hz)
  NormalityTest normality;
};

// The PSD reduced for a plot: bins 1 .. L/2 (no DC) averaged over log-spaced frequency bands.
struct SpectrumPoints {
  std::vector<double> frequency_hz;
  std::array<std::vector<double>, 3> density;  // per axis, unit^2/Hz
};

struct RecordNoise {
  std::string label;
  std::string date;
  long num_samples = 0;
  double rate_hz = kNaN;      // from the median sample interval
  double duration_s = kNaN;   // last t - first t
  std::array<AxisNoise, 3> axes;
  double band_low_hz = kNaN;  // the flat band the densities are averaged over
  double band_high_hz = kNaN;
  int band_bins = 0;
  int segment_length = 0;     // Welch segment, samples
  int num_segments = 0;
  double resolution_hz = kNaN;
  SpectrumPoints spectrum;
};

struct BiasRepeatability {
  std::vector<std::string> labels;  // the records used, one per day
  std::vector<std::string> dates;
  std::vector<Eigen::Vector3d> means;  // their means, unit
  int num_days = 0;
  Eigen::Vector3d std_of_means = Eigen::Vector3d::Constant(kNaN);   // sample std (n - 1), unit
  Eigen::Vector3d max_minus_min = Eigen::Vector3d::Constant(kNaN);  // unit
};

struct NoiseReport {
  std::string unit = "counts";  // "counts" or "m/s^2"
  std::string calibration_source;  // the calibration used; empty for counts
  std::vector<RecordNoise> records;
  BiasRepeatability repeatability;
  std::vector<std::string> warnings;  // e.g. too few days
};

// Analyses `records` (at least one). `calibration`, when not null, converts readings to m/s^2;
// it is only read during the call. Throws accelcal::Error: invalid options, no records, a
// record too short for the PSD (fewer than 16 samples) or with t not increasing, a constant
// axis, a calibration that needs temperatures the samples lack.
NoiseReport AnalyzeNoise(const std::vector<NoiseRecord>& records,
                         const NoiseAnalysisOptions& options = {},
                         const Calibration* calibration = nullptr);
// The same from sources; throws also when a source gives different samples at a later pass.
NoiseReport AnalyzeNoiseSources(const std::vector<NoiseRecordSource>& records,
                                const NoiseAnalysisOptions& options = {},
                                const Calibration* calibration = nullptr);

}  // namespace accelcal::analysis

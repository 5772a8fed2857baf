#include "accelcal/analysis/record_noise.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/core.h>

#include "accelcal/analysis/replay_selection.h"
#include "accelcal/base/error.h"

namespace accelcal::analysis {
namespace {

// Minimum number of PSD bins kept below the flat band: the lowest bins carry the window's
// leakage of drift and flicker.
constexpr int kExcludedLowBins = 4;
constexpr long kMinSamples = 16;

using Axes = std::array<double, 3>;

// One pass over the source: `visit(i, sample, value)` for every sample, value in the report's
// unit. Returns the samples visited; throws when a later pass does not see the first's count.
template <typename Visit>
long Pass(const NoiseRecordSource& source, const CalibrationApplier* applier, long expected,
          Visit&& visit) {
  long i = 0;
  source.replay([&](const Sample* samples, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k, ++i) {
      const Sample& s = samples[k];
      visit(i, s, applier ? Eigen::Vector3d(applier->Apply(s)) : s.raw_counts);
    }
  });
  if (expected >= 0 && i != expected)
    throw Error(fmt::format("record {}: it changed while it was read ({} samples, then {})",
                            source.label, expected, i));
  return i;
}

// The first pass: the count, t's span and steps, the first problem of each kind, the sums of
// the means and the largest magnitudes.
struct FirstPass {
  long n = 0;
  double t_first = kNaN;
  double t_last = kNaN;
  std::optional<std::string> t_problem;        // t does not increase
  std::optional<std::string> reading_problem;  // a raw reading not finite
  std::array<long, 3> first_bad_value{-1, -1, -1};  // a converted value not finite, per axis
  Axes sum_value{0.0, 0.0, 0.0};
  Axes sum_counts{0.0, 0.0, 0.0};
  Axes largest{0.0, 0.0, 0.0};
};

FirstPass ScanRecord(const NoiseRecordSource& source, const CalibrationApplier* applier,
                     ReplaySelection* median_interval) {
  FirstPass f;
  double t_previous = kNaN;
  f.n = Pass(source, applier, -1, [&](long i, const Sample& s, const Eigen::Vector3d& v) {
    if (i == 0) {
      f.t_first = s.t_s;
    } else if (const double d = s.t_s - t_previous; !(d > 0.0)) {
      if (!f.t_problem)
        f.t_problem = fmt::format("record {}: t does not increase at sample {} (t = {})",
                                  source.label, i, s.t_s);
    } else {
      median_interval->Add(d);
    }
    t_previous = f.t_last = s.t_s;
    for (int a = 0; a < 3; ++a) {
      const std::size_t k = static_cast<std::size_t>(a);
      if (!std::isfinite(s.raw_counts(a)) && !f.reading_problem)
        f.reading_problem =
            fmt::format("record {}: a reading at t = {} is not finite", source.label, s.t_s);
      if (!std::isfinite(v(a)) && f.first_bad_value[k] < 0) f.first_bad_value[k] = i;
      f.sum_value[k] += v(a);
      f.sum_counts[k] += s.raw_counts(a);
      f.largest[k] = std::max(f.largest[k], std::fabs(v(a)));
    }
  });
  return f;
}

// The checks in the order the whole-vector analysis made them.
void CheckFirstPass(const NoiseRecordSource& source, const FirstPass& f) {
  if (f.n < kMinSamples)
    throw Error(fmt::format("record {}: {} samples are too few for a noise analysis (at least 16)",
                            source.label, f.n));
  if (f.t_problem) throw Error(*f.t_problem);
  if (f.reading_problem) throw Error(*f.reading_problem);
  for (long i : f.first_bad_value)
    if (i >= 0) throw Error(fmt::format("Welch PSD: sample {} is not finite", i));
}

// Bins 1 .. L/2 averaged over at most max_points log-spaced bands; a band without a bin is
// skipped, so the low end keeps single bins.
SpectrumPoints ReduceSpectrum(const std::array<PowerSpectrum, 3>& psd, int max_points) {
  SpectrumPoints out;
  const std::vector<double>& f = psd[0].frequency_hz;
  const std::size_t last = f.size() - 1;
  const double f_lo = f[1];
  const double f_hi = f[last];
  const double log_step = std::log(f_hi / f_lo) / max_points;
  std::size_t k = 1;
  for (int band = 0; band < max_points && k <= last; ++band) {
    const double edge = band + 1 == max_points ? f_hi * 1.0001 : f_lo * std::exp(log_step * (band + 1));
    double sum_f = 0.0;
    std::array<double, 3> sum_p{0.0, 0.0, 0.0};
    int count = 0;
    for (; k <= last && f[k] < edge; ++k) {
      sum_f += f[k];
      for (std::size_t a = 0; a < 3; ++a) sum_p[a] += psd[a].density[k];
      ++count;
    }
    if (count == 0) continue;
    out.frequency_hz.push_back(sum_f / count);
    for (std::size_t a = 0; a < 3; ++a) out.density[a].push_back(sum_p[a] / count);
  }
  return out;
}

// The flat band's edges and the mean PSD over it, into r (the spectra in r's fields).
void FlatBand(const std::array<PowerSpectrum, 3>& psd, const NoiseAnalysisOptions& options,
              RecordNoise* r, Axes* band_sum) {
  const double nyquist_hz = 0.5 * r->rate_hz;
  r->band_low_hz =
      std::max(options.band_low_fraction * nyquist_hz, kExcludedLowBins * r->resolution_hz);
  r->band_high_hz = options.band_high_fraction * nyquist_hz;
  *band_sum = {0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < psd[0].frequency_hz.size(); ++k) {
    const double f = psd[0].frequency_hz[k];
    if (f < r->band_low_hz || f > r->band_high_hz) continue;
    for (std::size_t a = 0; a < 3; ++a) (*band_sum)[a] += psd[a].density[k];
    ++r->band_bins;
  }
  if (r->band_bins == 0)
    throw Error(fmt::format("record {}: no PSD bin in the flat band {:.3g}..{:.3g} Hz (record too "
                            "short: {} samples)", r->label, r->band_low_hz, r->band_high_hz,
                            r->num_samples));
}

}  // namespace

RecordNoise AnalyzeRecordNoise(const NoiseRecordSource& source, const NoiseAnalysisOptions& options,
                               const CalibrationApplier* applier) {
  ReplaySelection median_interval;
  const FirstPass f = ScanRecord(source, applier, &median_interval);
  CheckFirstPass(source, f);
  const double n = static_cast<double>(f.n);
  // The interval at index (n - 1) / 2 of the n - 1 sorted intervals, as nth_element finds it.
  bool interval_known = median_interval.EndPass(static_cast<std::uint64_t>((f.n - 1) / 2));

  // Normality is tested on the values divided by their largest magnitude (normality.h).
  Axes unit{}, sum_scaled{0.0, 0.0, 0.0};
  for (std::size_t a = 0; a < 3; ++a) unit[a] = f.largest[a] > 0.0 ? f.largest[a] : 1.0;
  double t_previous = kNaN;
  Pass(source, applier, f.n, [&](long i, const Sample& s, const Eigen::Vector3d& v) {
    for (std::size_t a = 0; a < 3; ++a) sum_scaled[a] += v(static_cast<int>(a)) / unit[a];
    if (!interval_known && i > 0) median_interval.Add(s.t_s - t_previous);
    t_previous = s.t_s;
  });
  const std::uint64_t median_index = static_cast<std::uint64_t>((f.n - 1) / 2);
  while (!interval_known) {
    interval_known = median_interval.EndPass(median_index);
    if (interval_known) break;
    Pass(source, applier, f.n, [&](long i, const Sample& s, const Eigen::Vector3d&) {
      if (i > 0) median_interval.Add(s.t_s - t_previous);
      t_previous = s.t_s;
    });
  }

  RecordNoise r;
  r.label = source.label;
  r.date = source.date;
  r.num_samples = f.n;
  r.rate_hz = 1.0 / median_interval.Result();
  r.duration_s = f.t_last - f.t_first;
  const int segment_length = RequireSegmentLength(f.n, options.welch);

  Axes mean{}, mean_counts{}, mean_scaled{};
  for (std::size_t a = 0; a < 3; ++a) {
    mean[a] = f.sum_value[a] / n;
    mean_counts[a] = f.sum_counts[a] / n;
    mean_scaled[a] = sum_scaled[a] / n;
  }
  std::array<WelchAccumulator, 3> welch{WelchAccumulator(segment_length),
                                        WelchAccumulator(segment_length),
                                        WelchAccumulator(segment_length)};
  Axes ss{0.0, 0.0, 0.0}, ss_counts{0.0, 0.0, 0.0};
  Axes m2{0.0, 0.0, 0.0}, m3{0.0, 0.0, 0.0}, m4{0.0, 0.0, 0.0};
  Pass(source, applier, f.n, [&](long, const Sample& s, const Eigen::Vector3d& v) {
    for (std::size_t a = 0; a < 3; ++a) {
      const double x = v(static_cast<int>(a));
      const double counts = s.raw_counts(static_cast<int>(a));
      welch[a].Add(x);
      ss[a] += (x - mean[a]) * (x - mean[a]);
      ss_counts[a] += (counts - mean_counts[a]) * (counts - mean_counts[a]);
      const double d = x / unit[a] - mean_scaled[a];
      const double d2 = d * d;
      m2[a] += d2;
      m3[a] += d2 * d;
      m4[a] += d2 * d2;
    }
  });

  std::array<PowerSpectrum, 3> psd;
  for (std::size_t a = 0; a < 3; ++a) psd[a] = welch[a].Finish(r.rate_hz);
  r.segment_length = psd[0].segment_length;
  r.num_segments = psd[0].num_segments;
  r.resolution_hz = psd[0].resolution_hz;
  Axes band_sum{};
  FlatBand(psd, options, &r, &band_sum);
  for (std::size_t a = 0; a < 3; ++a) {
    AxisNoise& axis = r.axes[a];
    axis.mean = mean[a];
    axis.std = std::sqrt(ss[a] / (n - 1.0));
    axis.std_counts = std::sqrt(ss_counts[a] / (n - 1.0));
    // N, the convention of IEEE 952 and Kalibr (and of the Allan read-offs): one-sided PSD
    // = 2 N^2 for white noise.
    axis.density = std::sqrt(band_sum[a] / r.band_bins / 2.0);
    axis.normality = JarqueBeraOfMoments(f.n, m2[a] / n, m3[a] / n, m4[a] / n, axis.std_counts,
                                         options.normality_alpha,
                                         options.quantization_limit_counts);
  }
  r.spectrum = ReduceSpectrum(psd, options.max_spectrum_points);
  return r;
}

}  // namespace accelcal::analysis

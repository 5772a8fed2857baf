// The noise analysis read from a source in passes (noise_analysis.h): the same report, to the
// bit, whatever the pieces the source delivers; the figures against the test's own arithmetic
// over whole vectors (nth_element for the median interval, plain sums for mean and std, a
// direct DFT for Welch's average); a source that changes between passes refused.
#include <algorithm>
#include <cmath>
#include <complex>
#include <random>

#include <gtest/gtest.h>

#include "accelcal/analysis/noise_analysis.h"
#include "accelcal/analysis/welch_psd.h"
#include "accelcal/base/error.h"
#include "test_support.h"

namespace accelcal::analysis {
namespace {

// A still record at ~`rate_hz` with white noise and a slow drift on each axis, t jittered so
// that its intervals take thousands of values.
NoiseRecord JitteredRecord(long n, double rate_hz, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 2.5);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  NoiseRecord r{"jittered", "2026-11-26", {}};
  for (long i = 0; i < n; ++i) {
    Sample s;
    s.t_s = (static_cast<double>(i) + jitter(rng)) / rate_hz;
    s.raw_counts = {2048.0 + std::round(noise(rng)), 2040.0 + std::round(noise(rng)) + 1e-4 * i,
                    2400.0 + noise(rng)};
    s.temp_c = 25.0;
    r.samples.push_back(s);
  }
  return r;
}

// Replays `record` in pieces of random sizes (1 to 997 samples), different at every pass.
NoiseRecordSource InPieces(const NoiseRecord& record, std::uint64_t seed) {
  auto rng = std::make_shared<std::mt19937_64>(seed);
  return {record.label, record.date, [&record, rng](const SamplePieceSink& sink) {
            std::size_t at = 0;
            while (at < record.samples.size()) {
              const std::size_t piece =
                  std::min<std::size_t>(1 + (*rng)() % 997, record.samples.size() - at);
              sink(record.samples.data() + at, piece);
              at += piece;
            }
          }};
}

void ExpectSameBits(const RecordNoise& a, const RecordNoise& b) {
  EXPECT_EQ(a.num_samples, b.num_samples);
  EXPECT_EQ(a.rate_hz, b.rate_hz);
  EXPECT_EQ(a.duration_s, b.duration_s);
  EXPECT_EQ(a.segment_length, b.segment_length);
  EXPECT_EQ(a.num_segments, b.num_segments);
  EXPECT_EQ(a.band_bins, b.band_bins);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(a.axes[i].mean, b.axes[i].mean) << i;
    EXPECT_EQ(a.axes[i].std, b.axes[i].std) << i;
    EXPECT_EQ(a.axes[i].std_counts, b.axes[i].std_counts) << i;
    EXPECT_EQ(a.axes[i].density, b.axes[i].density) << i;
    EXPECT_EQ(a.axes[i].normality.statistic, b.axes[i].normality.statistic) << i;
    EXPECT_EQ(a.spectrum.density[i], b.spectrum.density[i]) << i;
  }
  EXPECT_EQ(a.spectrum.frequency_hz, b.spectrum.frequency_hz);
}

TEST(NoiseSourceTest, PiecesDoNotChangeABit) {
  const NoiseRecord record = JitteredRecord(30000, 100.0, 11);
  const NoiseReport whole = AnalyzeNoise({record});
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const NoiseReport pieces = AnalyzeNoiseSources({InPieces(record, seed)});
    ASSERT_EQ(pieces.records.size(), 1u);
    ExpectSameBits(whole.records[0], pieces.records[0]);
  }
}

// The one-sided Welch PSD by the definition (welch_psd.h): segments of L at 50 % overlap, each
// minus its least-squares line, times the periodic Hann window, a direct DFT.
std::vector<double> DirectWelch(const std::vector<double>& x, int length, double rate_hz) {
  std::vector<double> sum(static_cast<std::size_t>(length / 2 + 1), 0.0);
  double window_power = 0.0;
  std::vector<double> w(static_cast<std::size_t>(length));
  for (int n = 0; n < length; ++n) {
    w[static_cast<std::size_t>(n)] = std::pow(std::sin(M_PI * n / length), 2);
    window_power += w[static_cast<std::size_t>(n)] * w[static_cast<std::size_t>(n)];
  }
  int segments = 0;
  for (std::size_t begin = 0; begin + static_cast<std::size_t>(length) <= x.size();
       begin += static_cast<std::size_t>(length / 2)) {
    // Least-squares line a + b n over the segment, by the normal equations.
    double s1 = 0, sn = 0, snn = 0, sy = 0, sny = 0;
    for (int n = 0; n < length; ++n) {
      const double y = x[begin + static_cast<std::size_t>(n)];
      s1 += 1; sn += n; snn += double(n) * n; sy += y; sny += n * y;
    }
    const double b = (s1 * sny - sn * sy) / (s1 * snn - sn * sn);
    const double a = (sy - b * sn) / s1;
    for (int k = 0; k <= length / 2; ++k) {
      std::complex<double> acc = 0.0;
      for (int n = 0; n < length; ++n) {
        const double y = (x[begin + static_cast<std::size_t>(n)] - a - b * n) *
                         w[static_cast<std::size_t>(n)];
        acc += y * std::polar(1.0, -2.0 * M_PI * k * n / length);
      }
      sum[static_cast<std::size_t>(k)] += std::norm(acc);
    }
    ++segments;
  }
  for (int k = 0; k <= length / 2; ++k)
    sum[static_cast<std::size_t>(k)] *= (k == 0 || k == length / 2 ? 1.0 : 2.0) /
                                        (rate_hz * window_power * segments);
  return sum;
}

TEST(NoiseSourceTest, FiguresAgreeWithWholeVectorArithmetic) {
  const NoiseRecord record = JitteredRecord(2000, 100.0, 12);  // Welch: L = 256, 14 segments
  const RecordNoise r = AnalyzeNoiseSources({InPieces(record, 4)}).records[0];
  std::vector<double> intervals;
  for (std::size_t i = 1; i < record.samples.size(); ++i)
    intervals.push_back(record.samples[i].t_s - record.samples[i - 1].t_s);
  std::nth_element(intervals.begin(), intervals.begin() + static_cast<long>(intervals.size() / 2),
                   intervals.end());
  EXPECT_EQ(r.rate_hz, 1.0 / intervals[intervals.size() / 2]);
  EXPECT_EQ(r.segment_length, 256);
  EXPECT_EQ(r.num_segments, 14);
  for (int a = 0; a < 3; ++a) {
    std::vector<double> x;
    for (const Sample& s : record.samples) x.push_back(s.raw_counts(a));
    double sum = 0.0;
    for (double v : x) sum += v;
    const double mean = sum / static_cast<double>(x.size());
    double ss = 0.0;
    for (double v : x) ss += (v - mean) * (v - mean);
    EXPECT_NEAR(r.axes[static_cast<std::size_t>(a)].mean, mean, 1e-12 * std::fabs(mean));
    EXPECT_NEAR(r.axes[static_cast<std::size_t>(a)].std,
                std::sqrt(ss / static_cast<double>(x.size() - 1)), 1e-12);
    const std::vector<double> direct = DirectWelch(x, 256, r.rate_hz);
    WelchAccumulator welch(256);
    for (double v : x) welch.Add(v);
    const PowerSpectrum psd = welch.Finish(r.rate_hz);
    ASSERT_EQ(psd.density.size(), direct.size());
    for (std::size_t k = 0; k < direct.size(); ++k)
      EXPECT_NEAR(psd.density[k], direct[k], 1e-9 * (1.0 + direct[k])) << "axis " << a << " bin " << k;
    const NormalityTest jb = JarqueBera(x, r.axes[static_cast<std::size_t>(a)].std_counts);
    EXPECT_NEAR(r.axes[static_cast<std::size_t>(a)].normality.statistic, jb.statistic,
                1e-9 * (1.0 + jb.statistic));
  }
}

TEST(NoiseSourceTest, ASourceThatChangesBetweenPassesIsRefused) {
  NoiseRecord record = JitteredRecord(3000, 100.0, 13);
  auto passes = std::make_shared<int>(0);
  NoiseRecordSource growing{"growing", "", [&record, passes](const SamplePieceSink& sink) {
                              // A file still being written: one more sample at every pass.
                              const std::size_t n = record.samples.size() - 10 +
                                                    static_cast<std::size_t>((*passes)++);
                              sink(record.samples.data(), n);
                            }};
  try {
    AnalyzeNoiseSources({growing});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(testing::Contains(e.what(), "record growing: it changed while it was read"))
        << e.what();
  }
}

TEST(NoiseSourceTest, TheFirstPassesProblemsComeInTheirOrder) {
  NoiseRecord record = JitteredRecord(100, 100.0, 14);
  record.samples[70].raw_counts(1) = NAN;
  record.samples[40].t_s = record.samples[39].t_s;
  try {
    AnalyzeNoiseSources({InPieces(record, 5)});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(testing::Contains(e.what(), "t does not increase at sample 40")) << e.what();
  }
  record.samples[40].t_s = 0.5 * (record.samples[39].t_s + record.samples[41].t_s);
  try {
    AnalyzeNoiseSources({InPieces(record, 6)});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_TRUE(testing::Contains(e.what(), "is not finite")) << e.what();
  }
}

}  // namespace
}  // namespace accelcal::analysis

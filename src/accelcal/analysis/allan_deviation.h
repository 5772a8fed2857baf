// Overlapping Allan deviation of one series of frequency-type data, streamed (bounded memory,
// a live curve at any time) or in one batch, with 68.3 % confidence bounds as Stable32 gives.
//
// Data and units:
//   - y_i, i = 0 .. N-1: one reading per sample, taken tau0_s apart (an accelerometer axis in
//     counts or m/s^2, a gyro axis in rad/s, a fractional frequency). The deviation has y's
//     unit; tau_s = m * tau0_s for the averaging factor m.
//   - Phase x_k = sum_{i<k} y_i (k = 0 .. N, N + 1 phase points). One term of averaging factor
//     m starting at j is d_j = x_{j+2m} - 2 x_{j+m} + x_j = m (mean of the second m readings -
//     mean of the first m), and AVAR(m) = sum_j d_j^2 / (2 m^2 num_terms) (NIST SP 1065 eq. 11).
//
// Exactness rule (overlap stride):
//   - m <= full_overlap_max_m: every j (stride 1), fully overlapping, exactly Stable32's OADEV;
//     num_terms = N + 1 - 2m without gaps.
//   - m > full_overlap_max_m: terms start every `stride` samples, j = 0, stride, 2 stride, ...,
//     stride = 2^L with L = floor(log2(m / overlap_positions)), so there are between
//     overlap_positions and 2 * overlap_positions term starts per m samples, and m is rounded
//     to the nearest multiple of stride. The estimator is still unbiased; its variance is that
//     of an overlapping estimator with stride factor S = m / stride (>= overlap_positions), and
//     the EDF is computed with that S (Greenhall & Riley). Statistical cost: none worth naming:
//     for S >= 64 their EDF equals the fully overlapping one within 0.2 % (their large-J
//     formulas depend on M/S only; checked for alpha = -2 .. 1 at m = 2^17 .. 2^22 over 12 h at
//     1 kHz), so the bounds are as tight; the strided value differs from the exact one by a small
//     fraction of its own uncertainty (see the test StridedBeyondFullOverlapAgreesStatistically).
//   - Curve() reports averaging factors with m <= N/4 (Stable32's limit for the overlapping
//     Allan deviation: its all-tau table of a 19982-point record ends at 4929 <= 19982/4).
//
// Gaps: a term is used only if none of its 2m readings is missing (cumulative missing counts
// kept beside the phase); num_terms counts the terms used, and the EDF is computed as for a
// gap-free record giving that many terms (slightly pessimistic: terms on both sides of a gap are
// less correlated than neighbours).
//
// Noise identification per point (for the EDF): from the m-averaged series z_k (non-overlapping
// means of m readings from the start; a block with a missing reading is left out and breaks the
// differences and lag-1 products through it): the lag-1 autocorrelation method when there are
// at least kLag1MinPoints averages, else the B1 ratio with the point's own Allan variance (see
// allan_confidence.h for both, normalised as Stable32). The streaming accumulator keeps, per m,
// running sums (value, square and lag-1 product sums of z and of its first and second
// differences: O(1) per factor) from which these statistics follow exactly, not the series; it
// matches the batch computation to rounding. One documented difference: where the batch
// function, like Stable32, tells white from flicker PM by R(n) = Mod-AVAR / AVAR when the B1
// ratio says "PM" (mu = -2, fewer than 30 averages), which needs the data, the accumulator
// takes white FM (alpha 0), the nearest FM noise. PM noise does not dominate inertial-sensor
// data at such long taus, and with few averages a white-FM record gives a PM-like B1 by chance
// often enough that the PM answer (whose EDF grows with ln m) would give far too narrow bounds.
//
// Errors: Add() of a NaN or infinite reading throws accelcal::Error (a gap must be declared with
// AddMissing, never smuggled in as a NaN); invalid options throw at construction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "accelcal/analysis/allan_confidence.h"

namespace accelcal {

struct AllanOptions {
  // Sample interval, s (> 0 and finite).
  double tau0_s = 0.0;
  // Log-spaced averaging factors round(10^(k / points_per_decade)), k = 0, 1, ..., always plus
  // every octave 1, 2, 4, ... (1 .. 100).
  int points_per_decade = 10;
  // Averaging factors up to this are computed fully overlapping (stride 1), exactly as Stable32.
  // Memory: the accumulator keeps 3 * (largest such factor) phase points and missing counts
  // (16 bytes each: 3 MiB at the default). >= overlap_positions and <= 2^24.
  int64_t full_overlap_max_m = int64_t{1} << 16;
  // Beyond full_overlap_max_m, terms start every 2^floor(log2(m / overlap_positions)) samples
  // (see the file comment). A power of two in 4 .. 4096.
  int overlap_positions = 64;
  // Largest averaging factor tracked (the grid is fixed at construction); the default covers
  // any record this program will meet (2^40 samples is 35 years at 1 kHz). >= 1.
  int64_t max_m = int64_t{1} << 40;
  // Two-sided probability of the bounds: one sigma, erf(1/sqrt 2) (Stable32's "0.683"). In (0, 1).
  double confidence = kOneSigmaConfidence;
  // Largest noise exponent the identification may report (-2 .. 2; Stable32: 2). The lag-1
  // method with ~100 averages now and then calls white FM "flicker PM" by chance, and the EDF of
  // flicker PM at large m is ~10 times that of white FM, so the bounds of that point come out
  // far too narrow; a caller that knows its data have no PM noise at long taus (velocity or
  // angle quantization only shows at short taus) may set 0. Points above it report max_alpha.
  int max_alpha = 2;
  // Chi-square quantiles of the bounds: exact, or Stable32's approximation above 100 edf.
  ChiSquareMethod chi_square = ChiSquareMethod::kExact;

  // Empty when usable, else a one-line description of the first problem.
  std::string Validate() const;
};

struct AllanPoint {
  int64_t m = 0;           // averaging factor
  double tau_s = 0.0;      // m * tau0_s
  int64_t stride = 1;      // samples between term starts (1: fully overlapping; m: non-overlapping)
  int64_t num_terms = 0;   // second differences used (Stable32's "#")
  double adev = 0.0;       // Allan deviation, unit of y
  int alpha = 0;           // noise exponent identified at this tau (S_y ~ f^alpha), -2 .. 2
  NoiseIdMethod noise_id = NoiseIdMethod::kNone;
  double edf = 0.0;        // equivalent degrees of freedom (Greenhall & Riley 2003)
  double adev_lo = 0.0;    // lower bound (confidence as in the options), unit of y
  double adev_hi = 0.0;    // upper bound
};

struct AllanCurve {
  double tau0_s = 0.0;
  int64_t samples = 0;          // readings seen, missing ones included
  int64_t missing_samples = 0;  // readings declared missing
  double confidence = kOneSigmaConfidence;
  std::vector<AllanPoint> points;  // ascending m
};

// The averaging-factor grid of these options (no N limit): octaves plus log-spaced factors up
// to options.max_m, rounded beyond full_overlap_max_m to their stride, ascending and unique.
std::vector<int64_t> AllanAveragingFactors(const AllanOptions& options);
// The stride the options use for averaging factor m (1 up to full_overlap_max_m).
int64_t AllanStride(const AllanOptions& options, int64_t m);

// Streaming accumulator for one series. Memory is fixed at construction (about
// 48 * full_overlap_max_m bytes, 3.3 MB at the default, plus a few kB per pyramid level),
// whatever the record length; each reading costs O(number of factors <= full_overlap_max_m) in
// tight loops that run every few tens of thousands of readings (about 45 ns per reading at the
// defaults: bench/README.md). Not thread-safe: one thread adds and asks for curves (or guard it).
class AllanAccumulator {
 public:
  explicit AllanAccumulator(const AllanOptions& options);  // throws accelcal::Error if invalid
  ~AllanAccumulator();
  AllanAccumulator(AllanAccumulator&&) noexcept;
  AllanAccumulator& operator=(AllanAccumulator&&) noexcept;

  // One reading. Throws accelcal::Error (and adds nothing) for NaN or infinity.
  void Add(double y);
  // Many readings, the same as calling Add for each (faster). Throws on the first non-finite
  // reading, naming its index in `y`; the readings before it are kept.
  void Add(std::span<const double> y);
  // A gap of n >= 0 readings (lost samples): no term containing one of them is used.
  void AddMissing(int64_t n);

  // The curve so far (points with at least one term and m <= samples() / 4). Cheap (about a
  // millisecond on a 12-hour record): callable about once a second on a growing record. Brings the
  // internal sums up to date first (hence not thread-safe even though const).
  AllanCurve Curve() const;

  int64_t samples() const;          // readings seen, missing included
  int64_t missing_samples() const;
  const AllanOptions& options() const;
  // Bytes of state held (buffers and per-factor sums): a constant after construction.
  size_t StateBytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Batch convenience: the accumulator fed the whole series (no gaps).
AllanCurve OverlappingAllan(std::span<const double> y, const AllanOptions& options);

// How the batch reference function places its terms.
enum class AllanEstimator {
  kOverlapping,     // every j (Stable32 "Overlapping Allan")
  kNonOverlapping,  // j = 0, m, 2m, ... (Stable32 "Allan")
};

// Direct (non-streaming) computation at exactly the given averaging factors, each 1 <= m <=
// (N-1)/2, with Stable32's noise identification (R(n) included) and bounds: the reference the
// accumulator is tested against. O(N) memory and O(N) time per factor. Throws accelcal::Error for
// a non-finite reading (naming its index), tau0_s <= 0, or a factor out of range.
AllanCurve AllanAtFactors(std::span<const double> y, double tau0_s,
                          std::span<const int64_t> factors, AllanEstimator estimator,
                          double confidence = kOneSigmaConfidence,
                          ChiSquareMethod chi_square = ChiSquareMethod::kExact);

}  // namespace accelcal

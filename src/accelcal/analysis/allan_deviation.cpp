#include "accelcal/analysis/allan_deviation.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include <Eigen/Core>

#include "accelcal/analysis/allan_kernels.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {

// Running sums of a series with gaps and of its lag-1 pairs (consecutive valid values), from
// which its lag-1 autocorrelation follows exactly as Lag1Autocorrelation computes it.
struct Lag1Sums {
  double n = 0, s = 0, ss = 0;            // values
  double np = 0, sa = 0, sb = 0, sab = 0;  // pairs (a = earlier, b = later)

  void AddValue(double w) {
    n += 1;
    s += w;
    ss += w * w;
  }
  void AddPair(double a, double b) {
    np += 1;
    sa += a;
    sb += b;
    sab += a * b;
  }
  double R1() const {
    if (n < 2) return std::nan("");
    const double mu = s / n;
    const double den = ss - n * mu * mu;
    const double num = sab - mu * (sa + sb) + np * mu * mu;
    return den > 0 ? (num / n) / (den / (n - 1)) : std::nan("");
  }
};

// Streaming statistics of the m-averaged series and of its first and second differences, for
// the noise identification, kept of the block sums m z_k rather than of the averages z_k (no
// division per block): the lag-1 autocorrelations do not depend on the scale, and the variance
// is divided by m^2 where it is used (IdentifyNoise). Blocks arrive in order k = 0, 1, 2, ...;
// a difference or pair involving an invalid block (one with a missing reading) is left out.
class AveragedSeriesStats {
 public:
  void AddBlock(bool valid, double z) {
    bool w_valid = false;
    bool v_valid = false;
    double w = 0, v = 0;
    if (valid) {
      d0_.AddValue(z);
      if (prev_z_valid_) {
        d0_.AddPair(prev_z_, z);
        w = z - prev_z_;
        w_valid = true;
        d1_.AddValue(w);
        if (prev_w_valid_) {
          d1_.AddPair(prev_w_, w);
          v = w - prev_w_;
          v_valid = true;
          d2_.AddValue(v);
          if (prev_v_valid_) d2_.AddPair(prev_v_, v);
        }
      }
    }
    prev_z_valid_ = valid;
    prev_z_ = z;
    prev_w_valid_ = w_valid;
    prev_w_ = w;
    prev_v_valid_ = v_valid;
    prev_v_ = v;
  }

  // The same as AddBlock(true, z[i]) for i = 0 .. n-1 (to rounding), as vector sums: each
  // series is laid out with its previous value in front, so its lag-1 pairs are (s[i], s[i+1]).
  void AddRun(const double* z, size_t n) {
    size_t i = 0;
    // The first values go one by one until the differences are primed.
    for (; i < n && !(prev_z_valid_ && prev_w_valid_ && prev_v_valid_); ++i) AddBlock(true, z[i]);
    const Eigen::Index k = static_cast<Eigen::Index>(n - i);
    if (k == 0) return;
    Eigen::ArrayXd zf(k + 1), wf(k + 1), vf(k + 1);
    zf(0) = prev_z_;
    zf.tail(k) = Eigen::Map<const Eigen::ArrayXd>(z + i, k);
    wf(0) = prev_w_;
    wf.tail(k) = zf.tail(k) - zf.head(k);
    vf(0) = prev_v_;
    vf.tail(k) = wf.tail(k) - wf.head(k);
    AddSeries(zf, &d0_);
    AddSeries(wf, &d1_);
    AddSeries(vf, &d2_);
    prev_z_ = zf(k);
    prev_w_ = wf(k);
    prev_v_ = vf(k);
  }

  int64_t points() const { return static_cast<int64_t>(d0_.n); }
  std::array<double, 3> Lag1() const { return {d0_.R1(), d1_.R1(), d2_.R1()}; }
  // Variance of the block sums about their mean, divided by their number (NaN below 2 points).
  double PopulationVariance() const {
    if (d0_.n < 2) return std::nan("");
    const double mu = d0_.s / d0_.n;
    return std::max(0.0, d0_.ss / d0_.n - mu * mu);
  }

 private:
  // Values s[1..k] and pairs (s[i], s[i+1]), i = 0 .. k-1, into `sums`.
  static void AddSeries(const Eigen::ArrayXd& s, Lag1Sums* sums) {
    const Eigen::Index k = s.size() - 1;
    const detail::Lag1RunSums run = detail::SumLag1Run(s.data(), static_cast<size_t>(k));
    sums->n += static_cast<double>(k);
    sums->s += run.values;  // both s and sb: summed once
    sums->ss += run.squares;
    sums->np += static_cast<double>(k);
    sums->sa += run.earlier;
    sums->sb += run.values;
    sums->sab += run.products;
  }

  Lag1Sums d0_, d1_, d2_;
  bool prev_z_valid_ = false, prev_w_valid_ = false, prev_v_valid_ = false;
  double prev_z_ = 0, prev_w_ = 0, prev_v_ = 0;
};

// Noise identification from the averaged series' statistics (see the header); avar is the
// Allan variance of the point, n_avg = valid readings / m (point->m set).
void IdentifyNoise(const AveragedSeriesStats& stats, double avar, double n_avg,
                   AllanPoint* point) {
  const int64_t n = stats.points();
  if (n >= kLag1MinPoints) {
    point->alpha = Lag1NoiseAlpha(stats.Lag1());
    point->noise_id = NoiseIdMethod::kLag1Acf;
    return;
  }
  const double md = static_cast<double>(point->m);
  const double b1 = stats.PopulationVariance() / (md * md) / avar;  // the averages' variance
  if (!std::isfinite(b1) || n_avg <= 1.0) {
    point->alpha = 0;
    point->noise_id = NoiseIdMethod::kNone;
    return;
  }
  point->noise_id = NoiseIdMethod::kB1Ratio;
  // B1's PM answer (mu = -2) is taken as white FM, the nearest FM noise: see the header.
  point->alpha = std::min(B1NoiseAlpha(b1, n_avg), 0);
}

void FillBounds(double confidence, ChiSquareMethod method, int64_t phase_points,
                AllanPoint* point) {
  point->edf = AllanEdf(point->alpha, point->m, point->stride, phase_points);
  const DeviationBounds b = ChiSquareDeviationBounds(point->adev, point->edf, confidence, method);
  point->adev_lo = b.lo;
  point->adev_hi = b.hi;
}

// One averaging factor of the accumulator: its Allan sums and averaged-series statistics.
struct Factor {
  int64_t m = 0;
  int level = 0;
  int64_t grid_m = 0;  // m in grid steps of its level (m / stride)
  int64_t next_j = 0;  // next term start, grid index
  double sum_sq = 0;   // sum of squared second differences of the phase
  int64_t terms = 0;
  int64_t next_block = 0;
  AveragedSeriesStats stats;
};

// One level of the decimation pyramid: the phase at every 2^level-th phase index (grid index g
// is phase index g << level), in a frame of its own (rebased at each compaction so the values
// stay small), and the cumulative count of missing readings there (exact integers).
struct Level {
  std::vector<double> x;
  std::vector<double> c;
  int64_t first = 0;  // grid index of x[0]
  size_t size = 0;
  size_t keep = 3;    // entries kept at compaction (>= 2 * largest grid_m + 1)
  int64_t next_up = 2;  // next grid index to carry up to the next level (even)
  std::vector<size_t> factors;
  // False until a missing reading reaches this level: until then every entry of c is 0 and is
  // neither written nor read (the common record has no gap; this saves a store per reading).
  bool has_missing = false;
};

}  // namespace

std::string AllanOptions::Validate() const {
  if (!(tau0_s > 0) || !std::isfinite(tau0_s)) return "allan: tau0_s must be positive and finite";
  if (points_per_decade < 1 || points_per_decade > 100) {
    return "allan: points_per_decade must be in 1..100";
  }
  if (overlap_positions < 4 || overlap_positions > 4096 ||
      (overlap_positions & (overlap_positions - 1)) != 0) {
    return "allan: overlap_positions must be a power of two in 4..4096";
  }
  if (full_overlap_max_m < overlap_positions || full_overlap_max_m > (int64_t{1} << 24)) {
    return "allan: full_overlap_max_m must be in overlap_positions..2^24";
  }
  if (max_m < 1 || max_m > (int64_t{1} << 50)) return "allan: max_m must be in 1..2^50";
  if (max_alpha < -2 || max_alpha > 2) return "allan: max_alpha must be in -2..2";
  if (!(confidence > 0 && confidence < 1)) return "allan: confidence must be in (0, 1)";
  if (chi_square != ChiSquareMethod::kExact && chi_square != ChiSquareMethod::kStable32) {
    return "allan: unknown chi_square method";
  }
  return "";
}

int64_t AllanStride(const AllanOptions& options, int64_t m) {
  if (m <= options.full_overlap_max_m) return 1;
  int64_t stride = 1;
  while (stride * 2 <= m / options.overlap_positions) stride *= 2;
  return stride;
}

std::vector<int64_t> AllanAveragingFactors(const AllanOptions& options) {
  std::set<int64_t> factors;
  for (int64_t p = 1; p <= options.max_m; p *= 2) factors.insert(p);
  for (int k = 0;; ++k) {
    const double v = std::round(std::pow(10.0, static_cast<double>(k) / options.points_per_decade));
    if (v > static_cast<double>(options.max_m)) break;
    int64_t m = static_cast<int64_t>(v);
    const int64_t stride = AllanStride(options, m);
    m = std::max<int64_t>(stride, (m + stride / 2) / stride * stride);
    if (m <= options.max_m) factors.insert(m);
  }
  return {factors.begin(), factors.end()};
}

struct AllanAccumulator::Impl {
  AllanOptions options;
  std::vector<Factor> factors;
  std::vector<Level> levels;
  int64_t samples = 0;
  int64_t missing = 0;
  bool have_ref = false;
  double ref = 0;  // first reading, subtracted from all (keeps the phase small)
  std::vector<double> scratch = std::vector<double>(4096);  // averages of a run of blocks
  std::vector<double> offset = std::vector<double>(4096);   // readings minus ref

  explicit Impl(const AllanOptions& o) : options(o) {
    int max_level = 0;
    for (int64_t m : AllanAveragingFactors(o)) {
      Factor f;
      f.m = m;
      const int64_t stride = AllanStride(o, m);
      while ((int64_t{1} << f.level) < stride) ++f.level;
      f.grid_m = m >> f.level;
      max_level = std::max(max_level, f.level);
      factors.push_back(f);
    }
    levels.resize(max_level + 1);
    for (size_t i = 0; i < factors.size(); ++i) {
      Level& l = levels[factors[i].level];
      l.factors.push_back(i);
      l.keep = std::max<size_t>(l.keep, 2 * factors[i].grid_m + 1);
    }
    for (size_t i = 0; i < levels.size(); ++i) {
      Level& l = levels[i];
      // Work happens once per `chunk` new entries; compaction copies `keep` entries then.
      const size_t chunk = i == 0 ? std::max<size_t>(4096, l.keep / 2) : std::max<size_t>(64, l.keep);
      l.x.assign(l.keep + chunk, 0.0);
      l.c.assign(l.keep + chunk, 0.0);
      l.size = 1;  // grid index 0: phase 0, nothing missing
    }
  }

  // Terms and blocks of the factors of level `li` up to its newest entry. The terms are summed
  // in slices of kSlice starts, all factors per slice, so the slice's first window stays in the
  // L1 cache across factors.
  void Process(size_t li) {
    constexpr int64_t kSlice = 2048;
    Level& l = levels[li];
    const int64_t last = l.first + static_cast<int64_t>(l.size) - 1;
    int64_t lowest = last;
    for (size_t fi : l.factors) lowest = std::min(lowest, factors[fi].next_j);
    for (int64_t slice = lowest; slice <= last; slice += kSlice) {
      for (size_t fi : l.factors) {
        Factor& f = factors[fi];
        const int64_t gm = f.grid_m;
        const int64_t end = std::min(slice + kSlice, last - 2 * gm + 1);  // exclusive
        if (end <= f.next_j) continue;
        const int64_t b0 = f.next_j - l.first;
        const Eigen::Index n = end - f.next_j;
        if (!l.has_missing || l.c[b0 + n - 1 + 2 * gm] == l.c[b0]) {  // none missing under these terms
          f.sum_sq += detail::SumSquaredSecondDifferences(
              l.x.data() + b0, l.x.data() + b0 + gm, l.x.data() + b0 + 2 * gm, static_cast<size_t>(n));
          f.terms += n;
        } else {
          Eigen::Map<const Eigen::ArrayXd> x0(l.x.data() + b0, n);
          Eigen::Map<const Eigen::ArrayXd> x1(l.x.data() + b0 + gm, n);
          Eigen::Map<const Eigen::ArrayXd> x2(l.x.data() + b0 + 2 * gm, n);
          Eigen::Map<const Eigen::ArrayXd> c0(l.c.data() + b0, n);
          Eigen::Map<const Eigen::ArrayXd> c2(l.c.data() + b0 + 2 * gm, n);
          f.sum_sq += (c2 == c0).select((x2 - 2.0 * x1 + x0).square(), 0.0).sum();
          f.terms += (c2 == c0).count();
        }
        f.next_j = end;
      }
    }
    for (size_t fi : l.factors) {
      Factor& f = factors[fi];
      const int64_t gm = f.grid_m;
      while ((f.next_block + 1) * gm <= last) {
        const int64_t g0 = f.next_block * gm - l.first;
        // A run of whole blocks (at most the scratch size) with no missing reading goes in one
        // call; a block with one goes alone.
        const int64_t blocks = std::min<int64_t>((last - l.first - g0) / gm,
                                                 static_cast<int64_t>(scratch.size()));
        if (!l.has_missing || l.c[g0 + blocks * gm] == l.c[g0]) {
          for (int64_t k = 0; k < blocks; ++k) scratch[k] = l.x[g0 + (k + 1) * gm] - l.x[g0 + k * gm];
          f.stats.AddRun(scratch.data(), static_cast<size_t>(blocks));
          f.next_block += blocks;
        } else {
          const int64_t g1 = g0 + gm;
          f.stats.AddBlock(l.c[g1] == l.c[g0], l.x[g1] - l.x[g0]);
          ++f.next_block;
        }
      }
    }
  }

  // Carries level li's new points with an even grid index up to level li+1: the increment of
  // such a point over the previous even one is level li+1's step.
  void Propagate(size_t li) {
    if (li + 1 >= levels.size()) return;
    Level& l = levels[li];
    const int64_t last = l.first + static_cast<int64_t>(l.size) - 1;
    for (int64_t g = l.next_up; g <= last; g += 2) {
      const int64_t i = g - l.first;
      Append(li + 1, l.x[i] - l.x[i - 2], l.has_missing ? l.c[i] - l.c[i - 2] : 0.0);
    }
    l.next_up = last + 1 + ((last + 1) & 1);  // the next even grid index
  }

  // Makes room in a full level: carries its points up, brings its factors up to date, keeps the
  // newest `keep` entries and rebases their phase on the oldest kept one.
  void Compact(size_t li) {
    Propagate(li);
    Process(li);
    Level& l = levels[li];
    const size_t drop = l.size - l.keep;
    const double base = l.x[drop];
    for (size_t i = 0; i < l.keep; ++i) l.x[i] = l.x[drop + i] - base;
    if (l.has_missing) std::copy(l.c.begin() + static_cast<long>(drop),
                                 l.c.begin() + static_cast<long>(drop + l.keep), l.c.begin());
    l.first += static_cast<int64_t>(drop);
    l.size = l.keep;
  }

  // Appends the next point (phase increment dx, missing-count increment dc) to level li.
  void Append(size_t li, double dx, double dc) {
    Level& l = levels[li];
    if (l.size == l.x.size()) Compact(li);
    const size_t i = l.size++;
    l.x[i] = l.x[i - 1] + dx;
    l.has_missing = l.has_missing || dc != 0.0;
    if (l.has_missing) l.c[i] = l.c[i - 1] + dc;
  }

  // Readings (already offset by ref) into level 0, in a tight loop between compactions.
  void AppendReadings(const double* v, size_t n) {
    Level& l = levels[0];
    while (n > 0) {
      if (l.size == l.x.size()) Compact(0);
      const size_t room = std::min(n, l.x.size() - l.size);
      double* x = l.x.data() + l.size;
      double* c = l.c.data() + l.size;
      double xi = x[-1];
      const double ci = c[-1];
      if (l.has_missing) {
        for (size_t k = 0; k < room; ++k) c[k] = ci;
      }
      for (size_t k = 0; k < room; ++k) {
        xi += v[k];
        x[k] = xi;
      }
      l.size += room;
      v += room;
      n -= room;
    }
  }

  void Flush() {
    for (size_t li = 0; li < levels.size(); ++li) {
      Propagate(li);
      Process(li);
    }
  }
};

AllanAccumulator::AllanAccumulator(const AllanOptions& options) {
  const std::string error = options.Validate();
  if (!error.empty()) throw Error(error);
  impl_ = std::make_unique<Impl>(options);
}
AllanAccumulator::~AllanAccumulator() = default;
AllanAccumulator::AllanAccumulator(AllanAccumulator&&) noexcept = default;
AllanAccumulator& AllanAccumulator::operator=(AllanAccumulator&&) noexcept = default;

void AllanAccumulator::Add(double y) { Add(std::span<const double>(&y, 1)); }

void AllanAccumulator::Add(std::span<const double> y) {
  Impl& s = *impl_;
  for (size_t done = 0; done < y.size();) {
    const size_t n = std::min(y.size() - done, s.offset.size());
    for (size_t i = 0; i < n; ++i) {
      const double v = y[done + i];
      if (!std::isfinite(v)) {
        s.AppendReadings(s.offset.data(), i);
        s.samples += static_cast<int64_t>(i);
        throw Error("allan: reading " + std::to_string(s.samples) + " (index " +
                    std::to_string(done + i) + " of this block) is not finite; declare lost " +
                    "readings with AddMissing");
      }
      if (!s.have_ref) {
        s.have_ref = true;
        s.ref = v;
      }
      s.offset[i] = v - s.ref;
    }
    s.AppendReadings(s.offset.data(), n);
    s.samples += static_cast<int64_t>(n);
    done += n;
  }
}

void AllanAccumulator::AddMissing(int64_t n) {
  if (n < 0) throw Error("allan: AddMissing needs n >= 0, got " + std::to_string(n));
  for (int64_t i = 0; i < n; ++i) impl_->Append(0, 0.0, 1.0);
  impl_->samples += n;
  impl_->missing += n;
}

AllanCurve AllanAccumulator::Curve() const {
  Impl& s = *impl_;
  s.Flush();
  AllanCurve curve;
  curve.tau0_s = s.options.tau0_s;
  curve.samples = s.samples;
  curve.missing_samples = s.missing;
  curve.confidence = s.options.confidence;
  for (const Factor& f : s.factors) {
    if (f.m > s.samples / 4) break;
    if (f.terms == 0) continue;
    AllanPoint p;
    p.m = f.m;
    p.tau_s = static_cast<double>(f.m) * s.options.tau0_s;
    p.stride = int64_t{1} << f.level;
    p.num_terms = f.terms;
    const double md = static_cast<double>(f.m);
    const double avar = f.sum_sq / (2.0 * md * md * static_cast<double>(f.terms));
    p.adev = std::sqrt(avar);
    IdentifyNoise(f.stats, avar, static_cast<double>(s.samples - s.missing) / md, &p);
    p.alpha = std::min(p.alpha, s.options.max_alpha);
    // The phase points of a gap-free record giving these terms (see the header on gaps).
    FillBounds(s.options.confidence, s.options.chi_square, (f.terms - 1) * p.stride + 2 * f.m + 1,
               &p);
    curve.points.push_back(p);
  }
  return curve;
}

int64_t AllanAccumulator::samples() const { return impl_->samples; }
int64_t AllanAccumulator::missing_samples() const { return impl_->missing; }
const AllanOptions& AllanAccumulator::options() const { return impl_->options; }

size_t AllanAccumulator::StateBytes() const {
  size_t bytes = sizeof(*this) + sizeof(Impl) + impl_->factors.capacity() * sizeof(Factor) +
                 impl_->levels.capacity() * sizeof(Level);
  for (const Level& l : impl_->levels) {
    bytes += (l.x.capacity() + l.c.capacity()) * sizeof(double) +
             l.factors.capacity() * sizeof(size_t);
  }
  return bytes;
}

AllanCurve OverlappingAllan(std::span<const double> y, const AllanOptions& options) {
  AllanAccumulator acc(options);
  acc.Add(y);
  return acc.Curve();
}

// ---- The direct batch computation ----

namespace {

// Sum of squared second differences of x at spacing m for starts 0, stride, ... <= last_start.
double SumSquares(const std::vector<double>& x, int64_t m, int64_t stride, int64_t* terms) {
  double sum = 0;
  int64_t n = 0;
  for (int64_t j = 0; j + 2 * m < static_cast<int64_t>(x.size()); j += stride, ++n) {
    const double d = x[j + 2 * m] - 2 * x[j + m] + x[j];
    sum += d * d;
  }
  *terms = n;
  return sum;
}

// Modified Allan variance at m (NIST SP 1065 eq. 14) from the phase x; NaN if 3m > N.
double ModifiedAvar(const std::vector<double>& x, int64_t m) {
  const int64_t points = static_cast<int64_t>(x.size());
  if (3 * m > points - 1) return std::nan("");
  std::vector<long double> s(x.size() + 1, 0.0L);  // s_k = sum_{i<k} x_i
  for (size_t i = 0; i < x.size(); ++i) s[i + 1] = s[i] + x[i];
  double sum = 0;
  int64_t n = 0;
  for (int64_t j = 0; j + 3 * m <= points; ++j, ++n) {
    const double d = static_cast<double>(s[j + 3 * m] - 3 * s[j + 2 * m] + 3 * s[j + m] - s[j]);
    sum += d * d;
  }
  const double md = static_cast<double>(m);
  return sum / (2.0 * md * md * md * md * static_cast<double>(n));
}

}  // namespace

AllanCurve AllanAtFactors(std::span<const double> y, double tau0_s,
                          std::span<const int64_t> factors, AllanEstimator estimator,
                          double confidence, ChiSquareMethod chi_square) {
  if (!(tau0_s > 0) || !std::isfinite(tau0_s)) throw Error("allan: tau0_s must be positive");
  if (!(confidence > 0 && confidence < 1)) throw Error("allan: confidence must be in (0, 1)");
  const int64_t n = static_cast<int64_t>(y.size());
  for (int64_t i = 0; i < n; ++i) {
    if (!std::isfinite(y[i])) {
      throw Error("allan: reading " + std::to_string(i) + " is not finite");
    }
  }
  // Phase relative to the first reading, accumulated in extended precision.
  std::vector<double> x(y.size() + 1, 0.0);
  long double acc = 0;
  for (int64_t i = 0; i < n; ++i) {
    acc += static_cast<long double>(y[i]) - y[0];
    x[i + 1] = static_cast<double>(acc);
  }
  AllanCurve curve;
  curve.tau0_s = tau0_s;
  curve.samples = n;
  curve.confidence = confidence;
  for (int64_t m : factors) {
    if (m < 1 || 2 * m > n - 1) {
      throw Error("allan: averaging factor " + std::to_string(m) + " is outside 1.." +
                  std::to_string((n - 1) / 2) + " for " + std::to_string(n) + " readings");
    }
    AllanPoint p;
    p.m = m;
    p.tau_s = static_cast<double>(m) * tau0_s;
    p.stride = estimator == AllanEstimator::kOverlapping ? 1 : m;
    const double md = static_cast<double>(m);
    const double sum = SumSquares(x, m, p.stride, &p.num_terms);
    p.adev = std::sqrt(sum / (2.0 * md * md * static_cast<double>(p.num_terms)));
    const double avar = sum / (2.0 * md * md * static_cast<double>(p.num_terms));
    // The m-averaged series.
    std::vector<double> z(static_cast<size_t>(n / m));
    for (size_t k = 0; k < z.size(); ++k) z[k] = (x[(k + 1) * m] - x[k * m]) / md;
    if (static_cast<int64_t>(z.size()) >= kLag1MinPoints) {
      p.alpha = Lag1NoiseAlpha(Lag1Autocorrelations(z));
      p.noise_id = NoiseIdMethod::kLag1Acf;
    } else {
      double mean = 0, var = 0;
      for (double v : z) mean += v;
      mean /= static_cast<double>(z.size());
      for (double v : z) var += (v - mean) * (v - mean);
      var /= static_cast<double>(z.size());
      p.noise_id = NoiseIdMethod::kB1Ratio;
      p.alpha = B1NoiseAlpha(var / avar, static_cast<double>(n) / md);
      if (p.alpha == 2) {
        int64_t terms = 0;
        const double oavar = SumSquares(x, m, 1, &terms) / (2.0 * md * md * terms);
        p.alpha = ResolvePhaseNoise(ModifiedAvar(x, m) / oavar, m);
      }
    }
    FillBounds(confidence, chi_square, n + 1, &p);
    curve.points.push_back(p);
  }
  return curve;
}

}  // namespace accelcal

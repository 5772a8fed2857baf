#include "accelcal/calibration/settling.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <fmt/core.h>

#include "accelcal/base/chi_square.h"
#include "accelcal/calibration/fit/fit_capture.h"

namespace accelcal {
namespace {

// The tau grid's look counted as this many independent trials (2 s to 2 min against 10 s
// captures: neighbouring taus give nearly the same exponential).
constexpr double kTauTrials = 4.0;
constexpr double kQuantizationVarianceCounts2 = 1.0 / 12.0;

// One capture's finite samples, time from its first, less the common slope.
struct Series {
  const Capture* capture = nullptr;
  std::vector<double> since_first_s;
  std::vector<Eigen::Vector3d> raw_counts;
  double w_rad_s = 0.0;  // turntable: the stated speed (swing regressors); 0: none
  FitCapture fit;        // the plain mean and its covariance
  Eigen::Vector3d change_counts = Eigen::Vector3d::Constant(kNaN);  // D: previous mean less this
};

// A capture's exponential coefficient at one tau: A (counts), its noise-only variance, the mean
// of the exponential over the samples.
struct Approach {
  Eigen::Vector3d amplitude = Eigen::Vector3d::Zero();
  Eigen::Vector3d variance = Eigen::Vector3d::Constant(kNaN);
  double mean_exp = kNaN;
};

Approach FitApproach(const Series& s, double tau_s) {
  const int p = s.w_rad_s > 0.0 ? 4 : 2;
  const size_t n = s.since_first_s.size();
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(p, p);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(p, 3);
  Eigen::VectorXd row(p);
  double sum_exp = 0.0;
  auto fill = [&](size_t k) {
    const double t = s.since_first_s[k];
    row(0) = 1.0;
    row(1) = std::exp(-t / tau_s);
    if (p == 4) {
      row(2) = std::cos(s.w_rad_s * t);
      row(3) = std::sin(s.w_rad_s * t);
    }
  };
  for (size_t k = 0; k < n; ++k) {
    fill(k);
    sum_exp += row(1);
    normal += row * row.transpose();
    rhs += row * s.raw_counts[k].transpose();
  }
  Approach a;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(normal);
  if (ldlt.info() != Eigen::Success) return a;
  const Eigen::MatrixXd coef = ldlt.solve(rhs);
  const Eigen::MatrixXd inverse = ldlt.solve(Eigen::MatrixXd::Identity(p, p));
  Eigen::Vector3d rss = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < n; ++k) {
    fill(k);
    const Eigen::Vector3d r = s.raw_counts[k] - coef.transpose() * row;
    rss += r.cwiseAbs2();
  }
  const Eigen::Vector3d per_sample =
      (rss / static_cast<double>(n - static_cast<size_t>(p))).cwiseMax(kQuantizationVarianceCounts2);
  a.amplitude = coef.row(1).transpose();
  a.variance = per_sample * inverse(1, 1);
  a.mean_exp = sum_exp / static_cast<double>(n);
  return a;
}

// Per axis, A_ij = c_j D_ij over the captures, weighted by 1/var(A_ij): c, var(c), t.
struct LagFit {
  Eigen::Vector3d share = Eigen::Vector3d::Zero();
  Eigen::Vector3d share_variance = Eigen::Vector3d::Constant(kNaN);
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  std::vector<Approach> approaches;  // one per series
};

LagFit FitLag(const std::vector<Series>& series, double tau_s) {
  LagFit f;
  for (const Series& s : series) f.approaches.push_back(FitApproach(s, tau_s));
  const double n = static_cast<double>(series.size());
  for (int j = 0; j < 3; ++j) {
    double sww = 0.0, swa = 0.0;
    for (size_t i = 0; i < series.size(); ++i) {
      const double w = 1.0 / f.approaches[i].variance(j), d = series[i].change_counts(j);
      sww += w * d * d;
      swa += w * d * f.approaches[i].amplitude(j);
    }
    if (!(sww > 0.0)) return {};
    const double c = swa / sww;
    double rss = 0.0;
    for (size_t i = 0; i < series.size(); ++i) {
      const double r = f.approaches[i].amplitude(j) - c * series[i].change_counts(j);
      rss += r * r / f.approaches[i].variance(j);
    }
    // The scatter about the line, from the captures (a wander shows there), at least the noise's.
    const double scale2 = std::max(1.0, rss / (n - 1.0));
    f.share(j) = c;
    f.share_variance(j) = scale2 / sww;
    f.t(j) = c / std::sqrt(f.share_variance(j));
  }
  return f;
}

// The used captures with enough finite samples, in time order, each with the change of pose
// from the capture before it (any capture with a mean: a pose is a pose even when left out).
std::vector<Series> SeriesOf(const std::vector<Capture>& captures) {
  std::vector<const Capture*> ordered;
  for (const Capture& c : captures)
    if (c.stats().n >= 2 && std::isfinite(c.stats().t_first_s)) ordered.push_back(&c);
  std::stable_sort(ordered.begin(), ordered.end(), [](const Capture* a, const Capture* b) {
    return a->stats().t_first_s < b->stats().t_first_s;
  });
  std::vector<Series> out;
  for (size_t k = 1; k < ordered.size(); ++k) {
    const Capture& c = *ordered[k];
    if (!c.used() || c.samples.size() < 20) continue;
    Series s;
    s.capture = &c;
    if (c.kind == CaptureKind::kTurntable) {
      s.w_rad_s = RpmToRadPerS(c.rpm);
      if (!(s.w_rad_s > 0.0)) continue;
    }
    const double t0 = c.stats().t_first_s;
    for (const Sample& x : c.samples) {
      if (!std::isfinite(x.t_s) || !x.raw_counts.allFinite()) continue;
      s.since_first_s.push_back(x.t_s - t0);
      s.raw_counts.push_back(x.raw_counts);
    }
    if (s.since_first_s.size() < 20) continue;
    s.fit = MakeFitCapture(c);
    s.change_counts = ordered[k - 1]->stats().mean_counts - c.stats().mean_counts;
    if (!s.change_counts.allFinite()) continue;
    out.push_back(std::move(s));
  }
  return out;
}

// Takes out of every series each axis' pooled slope inside the captures (a drift or warm-up
// common to the session), about each capture's mean time so that its mean stays.
void RemoveCommonSlope(std::vector<Series>& series) {
  Eigen::Vector3d sxy = Eigen::Vector3d::Zero();
  double sxx = 0.0;
  std::vector<double> mean_t(series.size());
  for (size_t i = 0; i < series.size(); ++i) {
    const Series& s = series[i];
    double sum = 0.0;
    for (double t : s.since_first_s) sum += t;
    mean_t[i] = sum / static_cast<double>(s.since_first_s.size());
    for (size_t k = 0; k < s.since_first_s.size(); ++k) {
      const double dt = s.since_first_s[k] - mean_t[i];
      sxx += dt * dt;
      sxy += dt * (s.raw_counts[k] - s.fit.mean_counts);
    }
  }
  if (!(sxx > 0.0)) return;
  const Eigen::Vector3d slope = sxy / sxx;
  for (size_t i = 0; i < series.size(); ++i)
    for (size_t k = 0; k < series[i].since_first_s.size(); ++k)
      series[i].raw_counts[k] -= slope * (series[i].since_first_s[k] - mean_t[i]);
}

}  // namespace

SettlingFinding HandleSettling(std::vector<Capture>& captures, const SettlingOptions& options) {
  for (Capture& c : captures) c.settled.reset();
  SettlingFinding finding;
  std::vector<Series> series = SeriesOf(captures);
  finding.captures = static_cast<int>(series.size());
  if (finding.captures < std::max(3, options.min_captures)) return finding;
  RemoveCommonSlope(series);

  LagFit best;
  double best_score = -1.0, best_tau = kNaN;
  const int steps = std::max(2, options.tau_steps);
  for (int k = 0; k < steps; ++k) {
    const double tau = options.min_tau_s *
                       std::pow(options.max_tau_s / options.min_tau_s, k / static_cast<double>(steps - 1));
    LagFit f = FitLag(series, tau);
    if (f.approaches.empty()) continue;
    const double score = f.t.squaredNorm();
    if (score > best_score) {
      best_score = score;
      best_tau = tau;
      best = std::move(f);
    }
  }
  if (best.approaches.empty()) return finding;
  finding.tau_s = best_tau;
  finding.lag_share = best.share;
  finding.t_statistic = best.t;
  // The three axes together: sum t_j^2, chi-square with 3 dof for many captures; each t has
  // n - 1 dof (the scatter about the line is estimated), whose t^2 has mean (n - 1) / (n - 3).
  const double n = finding.captures;
  finding.critical_score = ChiSquareQuantile(1.0 - options.significance / kTauTrials, 3.0) * (n - 1.0) / (n - 3.0);
  finding.detected = best_score > finding.critical_score;
  if (!finding.detected) return finding;

  for (size_t i = 0; i < series.size(); ++i) {
    const Series& s = series[i];
    const double e = best.approaches[i].mean_exp;
    SettledReading settled;
    settled.offset_counts = best.share.cwiseProduct(s.change_counts) * e;
    settled.mean_counts = s.fit.mean_counts - settled.offset_counts;
    settled.mean_cov_counts2 = s.fit.mean_cov_counts2;
    for (int j = 0; j < 3; ++j)
      settled.mean_cov_counts2(j, j) += std::pow(s.change_counts(j) * e, 2) * best.share_variance(j);
    const double largest = settled.offset_counts.cwiseAbs().maxCoeff();
    if (largest > finding.largest_offset_counts) {
      finding.largest_offset_counts = largest;
      finding.largest_offset_label = s.capture->label.empty() ? fmt::format("capture {}", s.capture->id)
                                                              : s.capture->label;
    }
    for (Capture& c : captures)
      if (&c == s.capture) c.settled = settled;
  }
  return finding;
}

std::string SettlingWords(const SettlingFinding& f) {
  return fmt::format("limited by captures taken while the sensor was still settling after each "
                     "change of pose: the reading relaxed toward its new value with a time "
                     "constant of about {:.0f} s, still {:.1f} counts off on average over {} "
                     "(the largest); each capture's settled reading was used instead of its mean. "
                     "Wait at least {:.0f} s after setting the sensor down before capturing",
                     f.tau_s, f.largest_offset_counts, f.largest_offset_label, 3.0 * f.tau_s);
}

}  // namespace accelcal

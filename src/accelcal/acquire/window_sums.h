// Running sums over a window of samples: count, per-axis mean and variance of raw_counts, and the
// per-axis least-squares slope of raw_counts against t (the trend). Samples can be added and
// removed in O(1), so a window can grow (a capture in progress) or slide (the static-interval
// detector, the live stability monitor). Shared by detail/sliding_variance and
// capture_engine/static_stability: one computation of "how still is this window".
//
// Running sums of x and x^2 suffer cancellation when |x| is large against its spread (raw
// counts near 33000 with a spread of a few counts; session times of thousands of seconds over a
// window of one): the sums are kept relative to a shifted origin (x0, t0), normally the window's
// first sample. A sliding user should rebuild the sums from scratch now and then (every few
// thousand steps) so that rounding drift cannot build up.
//
// Units: counts for x, s for t, counts^2 for variances, counts per s for slopes.
#pragma once

#include <Eigen/Core>

namespace accelcal::detail {

class WindowSums {
 public:
  // Empties the sums and sets the origin the next samples are measured from.
  void Reset(const Eigen::Vector3d& origin_counts, double origin_t_s);

  void Add(const Eigen::Vector3d& x_counts, double t_s);
  // Removes a sample added before (exactly the same values).
  void Remove(const Eigen::Vector3d& x_counts, double t_s);

  long n() const { return n_; }
  // Per-axis mean, counts (NaN when empty).
  Eigen::Vector3d Mean() const;
  // Per-axis sample variance (n - 1 denominator), counts^2; NaN below 2 samples.
  Eigen::Vector3d Variance() const;
  // Per-axis least-squares slope of x against t, counts per s; NaN below 2 samples or when all
  // samples share one t.
  Eigen::Vector3d SlopePerS() const;

 private:
  Eigen::Vector3d origin_x_ = Eigen::Vector3d::Zero();
  double origin_t_ = 0.0;
  long n_ = 0;
  Eigen::Vector3d sum_x_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_xx_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_xt_ = Eigen::Vector3d::Zero();
  double sum_t_ = 0.0;
  double sum_tt_ = 0.0;
};

}  // namespace accelcal::detail

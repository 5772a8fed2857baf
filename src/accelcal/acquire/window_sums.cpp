#include "accelcal/acquire/window_sums.h"

#include "accelcal/base/capture.h"

namespace accelcal::detail {

void WindowSums::Reset(const Eigen::Vector3d& origin_counts, double origin_t_s) {
  *this = WindowSums{};
  origin_x_ = origin_counts;
  origin_t_ = origin_t_s;
}

void WindowSums::Add(const Eigen::Vector3d& x_counts, double t_s) {
  const Eigen::Vector3d d = x_counts - origin_x_;
  const double dt = t_s - origin_t_;
  ++n_;
  sum_x_ += d;
  sum_xx_ += d.cwiseProduct(d);
  sum_xt_ += d * dt;
  sum_t_ += dt;
  sum_tt_ += dt * dt;
}

void WindowSums::Remove(const Eigen::Vector3d& x_counts, double t_s) {
  const Eigen::Vector3d d = x_counts - origin_x_;
  const double dt = t_s - origin_t_;
  --n_;
  sum_x_ -= d;
  sum_xx_ -= d.cwiseProduct(d);
  sum_xt_ -= d * dt;
  sum_t_ -= dt;
  sum_tt_ -= dt * dt;
}

Eigen::Vector3d WindowSums::Mean() const {
  if (n_ == 0) return Eigen::Vector3d::Constant(kNaN);
  return origin_x_ + sum_x_ / static_cast<double>(n_);
}

Eigen::Vector3d WindowSums::Variance() const {
  if (n_ < 2) return Eigen::Vector3d::Constant(kNaN);
  const double nd = static_cast<double>(n_);
  const Eigen::Vector3d ss = sum_xx_ - sum_x_.cwiseProduct(sum_x_) / nd;
  return (ss / (nd - 1.0)).cwiseMax(0.0);  // rounding may leave a tiny negative
}

Eigen::Vector3d WindowSums::SlopePerS() const {
  if (n_ < 2) return Eigen::Vector3d::Constant(kNaN);
  const double nd = static_cast<double>(n_);
  const double stt = sum_tt_ - sum_t_ * sum_t_ / nd;  // centred sum of squares of t
  if (!(stt > 0.0)) return Eigen::Vector3d::Constant(kNaN);
  const Eigen::Vector3d sxt = sum_xt_ - sum_x_ * (sum_t_ / nd);
  return sxt / stt;
}

}  // namespace accelcal::detail

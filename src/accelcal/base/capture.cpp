#include "accelcal/base/capture.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/core.h>

namespace accelcal {

std::string_view CaptureKindToString(CaptureKind kind) {
  switch (kind) {
    case CaptureKind::kStatic: return "static";
    case CaptureKind::kTurntable: return "turntable";
  }
  return "?";
}

std::optional<CaptureKind> StringToCaptureKind(std::string_view text) {
  if (text == "static") return CaptureKind::kStatic;
  if (text == "turntable") return CaptureKind::kTurntable;
  return std::nullopt;
}

namespace {
constexpr std::array<std::string_view, 6> kAxisNames = {"+x", "-x", "+y", "-y", "+z", "-z"};
}  // namespace

std::string_view SensorAxisToString(SensorAxis axis) { return kAxisNames[static_cast<int>(axis)]; }

std::optional<SensorAxis> StringToSensorAxis(std::string_view text) {
  for (std::size_t i = 0; i < kAxisNames.size(); ++i)
    if (kAxisNames[i] == text) return static_cast<SensorAxis>(i);
  return std::nullopt;
}

Eigen::Vector3d SensorAxisVector(SensorAxis axis) {
  const int i = static_cast<int>(axis);
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  v(i / 2) = (i % 2 == 0) ? 1.0 : -1.0;
  return v;
}

std::string DescribeUp(const Eigen::Vector3d& up) {
  const Eigen::Vector3d u = up.normalized();
  const char* names[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    if (std::fabs(std::fabs(u[axis]) - 1.0) < 1e-6)
      return fmt::format("{}{}", u[axis] > 0 ? '+' : '-', names[axis]);
  }
  return fmt::format("({:.2f}, {:.2f}, {:.2f})", u.x(), u.y(), u.z());
}

void CaptureStats::Add(const Sample& s) {
  if (!s.raw_counts.allFinite() || !std::isfinite(s.t_s)) {
    any_non_finite = true;
    return;
  }
  ++n;
  const double inv_n = 1.0 / static_cast<double>(n);
  const Eigen::Vector3d delta = s.raw_counts - mean_counts;
  mean_counts += delta * inv_n;
  // Welford's co-moment update: C += (x - mean_old)(x - mean_new)^T; divided by n - 1 on read.
  comoment_counts2 += delta * (s.raw_counts - mean_counts).transpose();
  if (n == 1) {
    t_first_s = s.t_s;
    mean_t_s = 0.0;
    min_counts = max_counts = s.raw_counts;
  }
  t_last_s = s.t_s;
  mean_t_s += (s.t_s - mean_t_s) * inv_n;
  min_counts = min_counts.cwiseMin(s.raw_counts);
  max_counts = max_counts.cwiseMax(s.raw_counts);
  if (std::isfinite(s.temp_c)) {
    if (std::isnan(mean_temp_c)) {
      mean_temp_c = min_temp_c = max_temp_c = s.temp_c;
      temp_n_ = 0;
    }
    ++temp_n_;
    mean_temp_c += (s.temp_c - mean_temp_c) / static_cast<double>(temp_n_);
    min_temp_c = std::min(min_temp_c, s.temp_c);
    max_temp_c = std::max(max_temp_c, s.temp_c);
  }
}

Eigen::Matrix3d CaptureStats::Covariance() const {
  if (n < 2) return Eigen::Matrix3d::Constant(kNaN);
  return comoment_counts2 / static_cast<double>(n - 1);
}

Eigen::Matrix3d CaptureStats::MeanCovariance() const {
  if (n < 2) return Eigen::Matrix3d::Constant(kNaN);
  return Covariance() / static_cast<double>(n);
}

Eigen::Vector3d CaptureStats::StdCounts() const {
  if (n < 2) return Eigen::Vector3d::Constant(kNaN);
  return Covariance().diagonal().cwiseSqrt();
}

CaptureStats ComputeStats(const std::vector<Sample>& samples) {
  CaptureStats stats;
  for (const Sample& s : samples) stats.Add(s);
  return stats;
}

const CaptureStats& Capture::stats() const {
  if (stats_of_samples_ != samples.size()) {
    stats_ = ComputeStats(samples);
    stats_of_samples_ = samples.size();
  }
  return stats_;
}

void Capture::set_stats(const CaptureStats& stats) {
  stats_ = stats;
  stats_of_samples_ = samples.size();
}

double ReferenceMagnitudeMps2(CaptureKind kind, double gravity_mps2, double radius_m, double rpm) {
  if (kind == CaptureKind::kStatic) return gravity_mps2;
  const double w = RpmToRadPerS(rpm);
  const double centripetal_mps2 = w * w * radius_m;
  return std::hypot(gravity_mps2, centripetal_mps2);
}

}  // namespace accelcal

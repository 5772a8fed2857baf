#include "accelcal/acquire/capture_engine/noise_floor.h"

#include <algorithm>

#include <fmt/format.h>

namespace accelcal {
namespace {

double Median(std::vector<double> values) {
  if (values.empty()) return kNaN;
  const size_t half = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(half), values.end());
  const double upper = values[half];
  if (values.size() % 2 == 1) return upper;
  const double lower = *std::max_element(values.begin(), values.begin() + static_cast<long>(half));
  return 0.5 * (lower + upper);
}

}  // namespace

NoiseFloor NoiseFloor::FromQuietPeriod(const CaptureStats& quiet) {
  NoiseFloor floor;
  floor.std_counts = quiet.StdCounts();
  floor.source = fmt::format("quiet period of {:.1f} s ({} samples)",
                             quiet.t_last_s - quiet.t_first_s, quiet.n);
  return floor;
}

NoiseFloor NoiseFloor::Given(const Eigen::Vector3d& std_counts) {
  return {std_counts, "given"};
}

NoiseFloor NoiseFloor::FromCaptures(const std::vector<Capture>& captures) {
  std::vector<double> per_axis[3];
  for (const Capture& capture : captures) {
    if (!capture.used()) continue;
    const CaptureStats& stats = capture.stats();
    if (stats.n < 2) continue;
    const Eigen::Vector3d std_counts = stats.StdCounts();
    for (int axis = 0; axis < 3; ++axis) per_axis[axis].push_back(std_counts[axis]);
  }
  NoiseFloor floor;
  for (int axis = 0; axis < 3; ++axis) floor.std_counts[axis] = Median(per_axis[axis]);
  floor.source = fmt::format("median over {} captures", per_axis[0].size());
  return floor;
}

std::string NoiseFloor::Validate() const {
  if (!std_counts.allFinite() || (std_counts.array() < 0.0).any()) {
    return fmt::format("noise floor ({}, {}, {}) counts: must be finite and >= 0 on every axis",
                       std_counts.x(), std_counts.y(), std_counts.z());
  }
  return {};
}

}  // namespace accelcal

#include "accelcal/session/procedure.h"

#include <cmath>

namespace accelcal {

std::vector<Eigen::Vector3d> Procedure::TiltedPoses() const {
  std::vector<Eigen::Vector3d> out;
  for (const ProcedureStep& s : steps) {
    if (!IsStaticPoseStep(s.kind)) continue;
    if ((s.up.array().abs() > 1e-6).count() > 1) out.push_back(s.up);
  }
  return out;
}

bool ProcedureLimits::Any() const {
  return std::isfinite(max_residual_rms_mps2) || std::isfinite(max_residual_rms_noise) ||
         std::isfinite(max_bias_sigma_counts) || std::isfinite(max_scale_sigma_ppm) ||
         std::isfinite(max_misalignment_sigma_rad) || min_captures > 0;
}

}  // namespace accelcal

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
         AnyOnUncertainty() || AnyTolerance() || min_captures > 0;
}

bool ProcedureLimits::AnyOnUncertainty() const {
  return std::isfinite(max_bias_U_counts) || std::isfinite(max_scale_U_ppm) ||
         std::isfinite(max_misalignment_U_rad);
}

bool ProcedureLimits::AnyTolerance() const {
  return std::isfinite(bias_tolerance_counts) || std::isfinite(scale_tolerance_percent) ||
         std::isfinite(misalignment_tolerance_rad);
}

std::string_view DecisionRuleKey(DecisionRule rule) {
  return rule == DecisionRule::kGuardBand ? "guard_band" : "simple";
}

std::optional<DecisionRule> DecisionRuleFromKey(std::string_view key) {
  if (key == "simple") return DecisionRule::kSimpleAcceptance;
  if (key == "guard_band") return DecisionRule::kGuardBand;
  return std::nullopt;
}

}  // namespace accelcal

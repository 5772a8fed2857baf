#include "accelcal/session/procedure_target.h"

#include <cmath>

#include <fmt/format.h>

#include "accelcal/base/gravity.h"
#include "accelcal/session/procedure.h"

namespace accelcal {

bool ProcedureTarget::Any() const {
  return std::isfinite(bias_mg) || std::isfinite(scale_ppm) || std::isfinite(misalignment_mrad);
}

UncertaintyTarget ToUncertaintyTarget(const ProcedureTarget& target, const SensorModel& nominal) {
  UncertaintyTarget t;
  t.bias_counts = target.bias_mg * 1e-3 * kStandardGravityMps2 /* 1 g, the mg's own */ * nominal.scale_counts_per_mps2.minCoeff();
  t.scale_relative = target.scale_ppm * 1e-6;
  t.misalignment_rad = target.misalignment_mrad * 1e-3;
  return t;
}

TargetConflict CheckTargetAgainstLimits(const ProcedureTarget& target, const ProcedureLimits& limits,
                                        const SensorModel& nominal) {
  const UncertaintyTarget t = ToUncertaintyTarget(target, nominal);
  // The bias limit is in counts; compare at the largest scale (the mg target's loosest count).
  const double bias_U_counts =
      t.bias_counts * nominal.scale_counts_per_mps2.maxCoeff() / nominal.scale_counts_per_mps2.minCoeff();
  if (std::isfinite(t.bias_counts) && bias_U_counts > limits.max_bias_U_counts)
    return {"bias_mg", fmt::format("[target] bias_mg = {:g} allows a U of {:.3g} counts, above [limits] "
                       "max_bias_U_counts = {:g}: the plan would aim at a bias the certificate fails",
                       target.bias_mg, bias_U_counts, limits.max_bias_U_counts)};
  if (std::isfinite(t.scale_relative) && target.scale_ppm > limits.max_scale_U_ppm)
    return {"scale_ppm", fmt::format("[target] scale_ppm = {:g} is above [limits] max_scale_U_ppm = {:g}: "
                       "the plan would aim at a scale the certificate fails",
                       target.scale_ppm, limits.max_scale_U_ppm)};
  if (std::isfinite(t.misalignment_rad) && t.misalignment_rad > limits.max_misalignment_U_rad)
    return {"misalignment_mrad", fmt::format("[target] misalignment_mrad = {:g} is {:g} rad, above [limits] "
                       "max_misalignment_U_rad = {:g}: the plan would aim at an angle the certificate fails",
                       target.misalignment_mrad, t.misalignment_rad, limits.max_misalignment_U_rad)};
  return {};
}

}  // namespace accelcal

// The uncertainty budget's JSON form inside the calibration file ("uncertainty_budget"): every
// parameter's contributions, combined, effective dof, k and U. Infinite degrees of freedom are
// written as null (JSON has no infinity) and read back as infinity.
#pragma once

#include <string>

#include "accelcal/calibration/uncertainty_budget.h"
#include "accelcal/io/detail/json_values.h"

namespace accelcal::detail {

json BudgetToJson(const UncertaintyBudget& budget);
// Strict: a wrong type anywhere is an InputError naming the field ("uncertainty_budget....").
UncertaintyBudget BudgetFromJson(const json& j, const std::string& source);

}  // namespace accelcal::detail

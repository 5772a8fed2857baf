#include "accelcal/io/detail/budget_json.h"

#include <cmath>
#include <limits>

#include <fmt/core.h>

namespace accelcal::detail {
namespace {

constexpr const char* kField = "uncertainty_budget";

json DofJson(double dof) { return std::isfinite(dof) ? json(dof) : json(nullptr); }

double ReadDof(const json& j, const std::string& path, const std::string& source) {
  const double dof = OptionalFinite(j, "dof", path, source);
  return std::isnan(dof) ? std::numeric_limits<double>::infinity() : dof;
}

json ContributionJson(const BudgetContribution& c) {
  return {{"quantity", c.quantity},
          {"type", std::string(1, c.type)},
          {"standard_uncertainty", JsonNumber(c.standard_uncertainty)},
          {"quantity_unit", c.quantity_unit},
          {"sensitivity", JsonNumber(c.sensitivity)},
          {"contribution", JsonNumber(c.contribution)},
          {"dof", DofJson(c.dof)},
          {"note", c.note}};
}

BudgetContribution ReadContribution(const json& j, const std::string& path, const std::string& source) {
  if (!j.is_object()) FailField(source, path, "must be an object");
  BudgetContribution c;
  c.quantity = OptionalString(j, "quantity", path + ".", source);
  const std::string type = OptionalString(j, "type", path + ".", source, "B");
  if (type != "A" && type != "B") FailField(source, path + ".type", "must be \"A\" or \"B\"");
  c.type = type[0];
  c.standard_uncertainty = OptionalFinite(j, "standard_uncertainty", path + ".", source);
  c.quantity_unit = OptionalString(j, "quantity_unit", path + ".", source);
  c.sensitivity = OptionalFinite(j, "sensitivity", path + ".", source);
  c.contribution = OptionalFinite(j, "contribution", path + ".", source);
  c.dof = ReadDof(j, path + ".", source);
  c.note = OptionalString(j, "note", path + ".", source);
  return c;
}

json ParameterJson(const ParameterBudget& p) {
  json parts = json::array();
  for (const BudgetContribution& c : p.contributions) parts.push_back(ContributionJson(c));
  return {{"name", p.name},
          {"unit", p.unit},
          {"value", JsonNumber(p.value)},
          {"contributions", parts},
          {"combined", JsonNumber(p.combined)},
          {"effective_dof", DofJson(p.effective_dof)},
          {"coverage_factor", JsonNumber(p.coverage_factor)},
          {"expanded", JsonNumber(p.expanded)}};
}

ParameterBudget ReadParameter(const json& j, const std::string& path, const std::string& source) {
  if (!j.is_object()) FailField(source, path, "must be an object");
  ParameterBudget p;
  p.name = OptionalString(j, "name", path + ".", source);
  p.index = -1;
  for (int i = 0; i < kNumBaseParameters; ++i)
    if (ParameterName(i) == p.name) p.index = i;
  if (p.index < 0) FailField(source, path + ".name", "'" + p.name + "' is not one of the nine parameters");
  p.unit = OptionalString(j, "unit", path + ".", source);
  p.value = OptionalFinite(j, "value", path + ".", source);
  const json& parts = RequiredField(j, "contributions", path + ".", source);
  if (!parts.is_array()) FailField(source, path + ".contributions", "must be an array");
  for (size_t i = 0; i < parts.size(); ++i)
    p.contributions.push_back(ReadContribution(parts[i], fmt::format("{}.contributions[{}]", path, i), source));
  p.combined = RequiredFinite(j, "combined", path + ".", source);
  const double dof = OptionalFinite(j, "effective_dof", path + ".", source);
  p.effective_dof = std::isnan(dof) ? std::numeric_limits<double>::infinity() : dof;
  p.coverage_factor = RequiredFinite(j, "coverage_factor", path + ".", source);
  p.expanded = RequiredFinite(j, "expanded", path + ".", source);
  return p;
}

std::vector<std::string> ReadNames(const json& j, const std::string& path, const std::string& source) {
  std::vector<std::string> out;
  if (!j.contains("not_stated") || j.at("not_stated").is_null()) return out;
  const json& a = j.at("not_stated");
  if (!a.is_array()) FailField(source, path + "not_stated", "must be an array");
  for (size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_string()) FailField(source, fmt::format("{}not_stated[{}]", path, i), "must be a string");
    out.push_back(a[i].get<std::string>());
  }
  return out;
}

}  // namespace

json BudgetToJson(const UncertaintyBudget& budget) {
  json params = json::array();
  for (const ParameterBudget& p : budget.parameters) params.push_back(ParameterJson(p));
  return {{"coverage_probability", budget.coverage_probability},
          {"parameters", params},
          {"not_stated", budget.not_stated}};
}

UncertaintyBudget BudgetFromJson(const json& j, const std::string& source) {
  const std::string path = std::string(kField) + ".";
  if (!j.is_object()) FailField(source, kField, "must be an object");
  UncertaintyBudget b;
  b.coverage_probability = RequiredFinite(j, "coverage_probability", path, source);
  if (!(b.coverage_probability > 0.0 && b.coverage_probability < 1.0))
    FailField(source, path + "coverage_probability", "must be between 0 and 1");
  const json& params = RequiredField(j, "parameters", path, source);
  if (!params.is_array()) FailField(source, path + "parameters", "must be an array");
  for (size_t i = 0; i < params.size(); ++i)
    b.parameters.push_back(ReadParameter(params[i], fmt::format("{}parameters[{}]", path, i), source));
  b.not_stated = ReadNames(j, path, source);
  return b;
}

}  // namespace accelcal::detail

#include "accelcal/report/certificate_text.h"

#include <cmath>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/base/safe_text.h"

namespace accelcal {

std::string BudgetNumber(double v) {
  if (!std::isfinite(v)) return "-";
  if (v == 0.0) return "0";
  return fmt::format("{:.3g}", v);
}

std::string DofText(double dof) {
  if (std::isinf(dof)) return "inf";
  return std::isfinite(dof) ? fmt::format("{:.0f}", dof) : "-";
}

std::string CertificateResultsText(const ReportModel& m, TextWrapper wrap) {
  const Certificate& c = m.certificate;
  std::string out;
  for (const CertificateResult& r : c.results) {
    out += fmt::format("  {:<20} {}\n", r.quantity + ":", r.forms.empty() ? "-" : r.forms.front());
    for (size_t i = 1; i < r.forms.size(); ++i) out += fmt::format("  {:<20} = {}\n", "", r.forms[i]);
    if (!r.held && c.has_budget)
      out += fmt::format("  {:<20}   (k = {}, nu_eff = {})\n", "", BudgetNumber(r.coverage_factor),
                         DofText(r.effective_dof));
  }
  out += "\n" + wrap("  ", c.coverage, 2);
  out += "\n" + wrap("  ", c.limited_by, 2);
  if (!c.not_stated.empty())
    out += wrap("  Not stated (not in U): ", fmt::format("{}: the procedure's [equipment] gives no "
                                                        "uncertainty for it.", fmt::join(c.not_stated, ", ")), 4);
  return out;
}

std::string UncertaintyBudgetText(const ReportModel& m, TextWrapper wrap) {
  if (!m.budget) return "  No uncertainty budget was made for this calibration.\n";
  std::string out = wrap("  ", "Per parameter: each source's standard uncertainty u(x), its "
                               "sensitivity coefficient c (the fit's response, parameter unit per "
                               "unit of x) and its part |c| u(x) of the combined standard "
                               "uncertainty u_c, in the parameter's unit.", 2);
  for (const ParameterBudget& p : m.budget->parameters) {
    out += fmt::format("\n  {} ({}): u_c = {}, nu_eff = {}, k = {}, U = {}\n", p.name, p.unit,
                       BudgetNumber(p.combined), DofText(p.effective_dof), BudgetNumber(p.coverage_factor),
                       BudgetNumber(p.expanded));
    out += "    Source            Type  u(x)      Unit           c         |c| u(x)   dof\n";
    for (const BudgetContribution& b : p.contributions) {
      const std::string unit = b.type == 'A' ? p.unit : b.quantity_unit;
      out += fmt::format("    {:<17} {:<4}  {:<9} {:<14} {:<9} {:<10} {}\n", ShortDisplayText(b.quantity, 17),
                         std::string(1, b.type), BudgetNumber(b.standard_uncertainty), ShortDisplayText(unit, 14),
                         b.type == 'A' ? std::string("1") : BudgetNumber(b.sensitivity),
                         BudgetNumber(b.contribution), DofText(b.dof));
    }
  }
  // The notes once, not per parameter.
  out += "\n";
  if (!m.budget->parameters.empty())
    for (const BudgetContribution& b : m.budget->parameters.front().contributions)
      if (!b.note.empty()) out += wrap("  " + b.quantity + ": ", DisplayText(b.note), 4);
  return out;
}

std::string CertificateStatementsText(const ReportModel& m, TextWrapper wrap) {
  const Certificate& c = m.certificate;
  std::string out = wrap("  Method: ", DisplayText(c.method), 4);
  out += "  Equipment:\n";
  if (c.equipment.empty()) out += "    none listed by the procedure\n";
  for (const EquipmentItem& e : c.equipment)
    out += wrap("    ", fmt::format("{}: {}, id {}, u = {}", InfoOf(e.role).key, DisplayText(e.name),
                                    e.identification.empty() ? "not recorded" : DisplayText(e.identification),
                                    DescribeUncertainty(e)), 6);
  out += wrap("  Ambient conditions: ", c.ambient, 4);
  out += "  Traceability:\n";
  for (const std::string& t : c.traceability) out += wrap("    ", DisplayText(t), 6);
  out += wrap("  Decision rule: ", c.decision_rule, 4);
  out += wrap("  Conformity: ", c.conformity, 4);
  return out;
}

}  // namespace accelcal

#include "accelcal/report/certificate.h"

#include <cctype>
#include <cmath>
#include <cstdint>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/base/gravity.h"
#include "accelcal/report/limited_by_text.h"
#include "accelcal/report/report_model.h"
#include "accelcal/report/uncertainty_text.h"

namespace accelcal {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMgMps2 = kStandardGravityMps2 * 1e-3;  // 1 mg (of standard gravity), m/s^2

std::uint32_t Fnv1a(const std::string& text) {
  std::uint32_t h = 2166136261u;
  for (unsigned char c : text) {
    h ^= c;
    h *= 16777619u;
  }
  return h;
}

// "2051.334 +- 0.044 counts"; without "+- U" when there is none.
std::string Form(double value, double expanded, const std::string& unit, bool sign = false) {
  const RoundedResult r = RoundToUncertainty(value, expanded);
  std::string v = r.value;
  if (sign && !v.empty() && v[0] != '-' && v != "-") v = "+" + v;
  return r.uncertainty == "-" ? fmt::format("{} {}", v, unit) : fmt::format("{} +- {} {}", v, r.uncertainty, unit);
}

CertificateResult Result(const ReportInputs& in, int i, const ReportParameter& p) {
  const Calibration& cal = in.calibration;
  CertificateResult r;
  r.name = p.name;
  r.held = p.held;
  const ParameterBudget* b = cal.budget ? cal.budget->Find(i) : nullptr;
  double u_expanded = kNaN;
  if (b != nullptr) {
    u_expanded = b->expanded;
    r.coverage_factor = b->coverage_factor;
    r.effective_dof = b->effective_dof;
  } else if (!p.held) {
    u_expanded = 2.0 * p.sigma;  // no budget: k = 2 on the fit's 1-sigma, stated so
    r.coverage_factor = 2.0;
  }
  const char axis = "xyz"[i % 3];
  if (i <= kBiasZ) {
    r.quantity = fmt::format("offset {}", axis);
    const double k = cal.model.scale_counts_per_mps2(i);
    const double nominal = in.nominal_bias_counts ? (*in.nominal_bias_counts)(i) : 0.0;
    const double offset_mps2 = (p.value - nominal) / k;
    r.forms = {Form(p.value, u_expanded, "counts"),
               Form(offset_mps2, u_expanded / k, "m/s^2", true) +
                   fmt::format(" from {:g} counts", nominal),
               Form(offset_mps2 / kMgMps2, u_expanded / k / kMgMps2, "mg", true)};
  } else if (i <= kScaleZ) {
    r.quantity = fmt::format("scale {}", axis);
    r.forms = {Form(p.value, u_expanded, "counts/(m/s^2)"),
               Form(p.value * kStandardGravityMps2, u_expanded * kStandardGravityMps2, "counts/g")};
  } else {
    r.quantity = "misalignment " + p.name;
    r.forms = {Form(p.value, u_expanded, "rad", true), Form(p.value * 1e3, u_expanded * 1e3, "mrad", true),
               Form(p.value * 180.0 / kPi, u_expanded * 180.0 / kPi, "deg", true)};
  }
  if (p.held) r.forms.front() += " (held, not fitted)";
  return r;
}

std::string Method(const ReportInputs& in, const ReportModel& m) {
  int statics = 0, runs = 0;
  for (const CalibrationCapture& c : in.calibration.captures) {
    if (!c.used) continue;
    (c.kind == CaptureKind::kTurntable ? runs : statics) += 1;
  }
  std::string effects = "none adopted";
  if (!m.effects.empty()) {
    std::vector<std::string> names;
    for (const ReportEffect& e : m.effects) names.push_back(e.name);
    effects = fmt::format("adopted: {}", fmt::join(names, ", "));
  }
  return fmt::format(
      "Magnitude method{}: {} still poses on the prism and {} turntable runs; the nine "
      "parameters (bias, scale, misalignment) fitted by weighted least squares to the magnitude "
      "of the specific force against local gravity and the centripetal reference w^2 r; a "
      "diagnosis of effects the model lacks ({}).",
      m.meta.procedure.empty() ? std::string() : " of the procedure \"" + m.meta.procedure + "\"",
      statics, runs, effects);
}

std::string Ambient(const ReportModel& m) {
  const std::string temp = std::isfinite(m.temp_min_c)
                               ? fmt::format("temperature of the sensor {:.1f} .. {:.1f} degC over the captures",
                                             m.temp_min_c, m.temp_max_c)
                               : "temperature not recorded";
  return temp + "; humidity and air pressure not recorded.";
}

std::vector<std::string> Traceability(const ReportInputs& in) {
  std::vector<std::string> out;
  const GravitySpec& g = in.calibration.gravity;
  out.push_back("Local gravity: " + g.Describe() + ".");
  for (const EquipmentItem& item : in.equipment) {
    const EquipmentRoleInfo& info = InfoOf(item.role);
    const std::string id = item.identification.empty() ? std::string(" (not identified)")
                           : IsPlaceholderId(item.identification) ? " (" + item.identification + ": not identified)"
                                                                  : " (" + item.identification + ")";
    out.push_back(fmt::format("{}: {}{}, u = {}; {}{}.", info.quantity, item.name, id, DescribeUncertainty(item),
                              item.traceability.empty() ? "the procedure states no traceability"
                                                        : "traced to " + item.traceability,
                              item.calibration.empty() ? "" : "; its calibration: " + item.calibration));
  }
  if (in.equipment.empty())
    out.push_back("The procedure lists no equipment ([equipment]): the radius, speed, leveling "
                  "and prism are not traced.");
  return out;
}

// The decision rule as the procedure states it (ILAC-G8:09/2019): the limits on U, the
// tolerances' rule, the fit's checks, and any first-format limit read by the stated rule.
std::string DecisionRuleText(const std::optional<ProcedureLimits>& limits) {
  if (!limits || !limits->Any()) return "None: the procedure states no limits.";
  std::vector<std::string> parts;
  if (limits->AnyOnUncertainty())
    parts.push_back("each limit on U is compared with the U (k = 2) of this certificate's budget, type A "
                    "and B; a U over its limit means the calibration cannot show conformity");
  if (limits->AnyTolerance())
    parts.push_back(limits->decision_rule == DecisionRule::kGuardBand
                        ? "each tolerance on the values by a guard band (ILAC-G8:09/2019, 4.2.2, binary "
                          "statement, w = U): a value conforms only within the tolerance narrowed by its "
                          "U, so that a false accept is unlikely (about 2.5 % at most)"
                        : "each tolerance on the values by simple acceptance (ILAC-G8:09/2019, 4.2.1): "
                          "the value as found within the tolerance conforms; its uncertainty neither "
                          "widens nor narrows the tolerance");
  if (limits->min_captures > 0 || std::isfinite(limits->max_residual_rms_mps2) ||
      std::isfinite(limits->max_residual_rms_noise))
    parts.push_back("the fit's checks (captures used, residual RMS) as found");
  std::string out = fmt::format("{}.", fmt::join(parts, "; "));
  out[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[0])));
  if (!limits->converted.empty())
    out += fmt::format(" The procedure states some limits on the fit's 1-sigma, read as limits on U = "
                       "2 x 1-sigma: {}.", fmt::join(limits->converted, "; "));
  return out;
}

std::string NotMet(const LimitCheck& c) {
  if (c.on_uncertainty) return "cannot show conformity: " + (c.why.empty() ? c.what : c.why);
  if (!c.why.empty()) return c.why;
  return fmt::format("{} {:.4g}{} {} {:.4g}", c.what, c.value, c.unit.empty() ? "" : " " + c.unit,
                     c.at_least ? "below" : "beyond", c.limit);
}

std::string Conformity(const ReportModel& m) {
  switch (m.verdict) {
    case Verdict::kPass:
      return fmt::format("Conforms: every limit of the procedure is met ({} checks), by the decision "
                         "rule above.", m.checks.size());
    case Verdict::kFail: {
      std::vector<std::string> failed;
      for (const LimitCheck& c : m.checks)
        if (!c.pass) failed.push_back(NotMet(c));
      return fmt::format("Does not conform: {}.", fmt::join(failed, "; "));
    }
    case Verdict::kIncomplete:
      return fmt::format("No statement of conformity: {} the session is incomplete: {}.",
                         m.checks.empty() ? "no limits are stated, and" : "the limits are met but",
                         fmt::join(m.incomplete, "; "));
    case Verdict::kNoLimits: break;
  }
  return "No statement of conformity: the procedure states no limits.";
}

}  // namespace

std::string CertificateNumber(const std::string& session_name, const SensorModel& model) {
  std::string name;
  for (char c : session_name)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') name += c;
  if (name.size() > 32) name.resize(32);
  if (name.empty()) name = "FILE";
  std::string key = session_name;
  const auto v = model.ToVector();
  for (int i = 0; i < v.size(); ++i) key += fmt::format("|{:.17g}", v(i));
  return fmt::format("ACC-{}-{:08X}", name, Fnv1a(key));
}

Certificate MakeCertificate(const ReportInputs& in, const ReportModel& m) {
  Certificate c;
  // The lab's number once the session is published (docs/lab.md), else the session's own.
  c.number = m.meta.certificate_number.empty() ? CertificateNumber(m.meta.session_name, in.calibration.model)
                                               : m.meta.certificate_number;
  c.simulated = m.meta.source.rfind("sim", 0) == 0;
  c.method = Method(in, m);
  c.equipment = in.equipment;
  c.ambient = Ambient(m);
  c.has_budget = in.calibration.budget.has_value();
  for (size_t i = 0; i < m.parameters.size(); ++i)
    c.results.push_back(Result(in, static_cast<int>(i), m.parameters[i]));
  if (c.has_budget) {
    c.not_stated = in.calibration.budget->not_stated;
    c.coverage = fmt::format(
        "The expanded uncertainty U = k u_c is the combined standard uncertainty u_c (type A from "
        "the fit's covariance; type B from each reference quantity's standard uncertainty, "
        "propagated with the fit's sensitivity coefficients) multiplied by the coverage factor k "
        "of Student's t at the effective degrees of freedom (Welch-Satterthwaite), for a "
        "coverage probability of about {:g} % (JCGM 100:2008). Results are rounded to two "
        "significant digits of U.",
        in.calibration.budget->coverage_probability * 100.0);
  } else {
    c.coverage = "No uncertainty budget was made for this calibration: U is twice the fit's "
                 "1-sigma (type A alone, k = 2); the reference quantities' uncertainties are not "
                 "included.";
  }
  c.limited_by = LimitedByStatement(in.calibration);
  c.traceability = Traceability(in);
  c.decision_rule = DecisionRuleText(in.limits);
  c.conformity = Conformity(m);
  return c;
}

}  // namespace accelcal

#include "accelcal/report/limit_checks.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/base/sensor_model.h"

namespace accelcal {
namespace {

constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;

// `v` to two significant digits, without an exponent: "4700", "15", "0.073".
std::string TwoDigits(double v) {
  if (!std::isfinite(v)) return "-";
  if (v == 0.0) return "0";
  const int magnitude = static_cast<int>(std::floor(std::log10(std::fabs(v))));
  const double step = std::pow(10.0, magnitude - 1);
  return fmt::format("{:.{}f}", std::round(v / step) * step, std::max(0, 1 - magnitude));
}

// `v` floored to two significant digits: an uncertainty to reach, "or better".
double FloorTwoDigits(double v) {
  if (!(v > 0.0) || !std::isfinite(v)) return v;
  const double step = std::pow(10.0, std::floor(std::log10(v)) - 1);
  return std::floor(v / step * (1.0 + 1e-12)) * step;
}

// A reference quantity's uncertainty in the unit the bench states it (the procedure file's).
struct BenchUnit {
  double scale;      // bench value = SI value * scale
  const char* unit;
};
BenchUnit BenchUnitOf(const std::string& quantity) {
  if (quantity == "radius") return {1e3, "mm"};
  if (quantity == "turntable speed") return {100.0, "%"};
  if (quantity == "table tilt" || quantity == "prism squareness") return {kDegPerRad, "deg"};
  return {1.0, "m/s^2"};
}

// What to do for `quantity` to be known to `u_si` (SI) or better.
std::string WhatToDo(const std::string& quantity, double u_si) {
  const BenchUnit w = BenchUnitOf(quantity);
  const double u = FloorTwoDigits(u_si * w.scale);
  if (quantity == "gravity")
    return u >= 5e-4 ? "give the local gravity (the place's latitude and altitude: u 0.0005 m/s^2, "
                       "or a measured value)"
                     : fmt::format("give a measured local gravity, u {:g} m/s^2 or better", u);
  if (quantity == "radius") return fmt::format("measure the radius to {:g} mm or better", u);
  if (quantity == "turntable speed")
    return fmt::format("check the turntable's speed to {:g} % or better (a calibrated tachometer)", u);
  if (quantity == "table tilt") return fmt::format("level the table to {:g} deg or better", u);
  return fmt::format("know the {} to {:g} {} or better", quantity, u, w.unit);
}

std::string WithUnit(double v, const std::string& unit) {
  return unit.empty() ? TwoDigits(v) : TwoDigits(v) + " " + unit;
}

const char* const kGroupNames[3] = {"bias", "scale", "misalignment"};

// A group's parameters in the unit of its limit: biases in counts, scales in ppm of the scale,
// misalignments in rad; `text_scale` turns the limit's unit into the remedy's (rad -> mrad).
struct Group {
  int first;             // kBiasX, kScaleX, kMisYZ
  std::string unit;      // of the limit
  double text_scale;
  std::string text_unit;
};

Group GroupOf(int first) {
  if (first == kScaleX) return {first, "ppm", 1.0, "ppm"};
  if (first == kMisYZ) return {first, "rad", 1e3, "mrad"};
  return {first, "counts", 1.0, "counts"};
}

// Parameter `i` in its group's limit unit (per unit of the parameter's own).
double ToLimitUnit(const Calibration& cal, int i) {
  return i >= kScaleX && i <= kScaleZ ? 1e6 / cal.model.scale_counts_per_mps2(i - kScaleX) : 1.0;
}

void CheckUncertainty(const Calibration& cal, int first, double limit, std::vector<LimitCheck>* out) {
  if (!std::isfinite(limit)) return;
  const Group g = GroupOf(first);
  LimitCheck c;
  c.what = fmt::format("{} U (k = 2)", kGroupNames[(first - kBiasX) / 3]);
  c.unit = g.unit;
  c.limit = limit;
  c.on_uncertainty = true;
  int worst = -1;
  for (int i = first; i < first + 3; ++i) {
    const double u = CertificateExpandedUncertainty(cal, i) * ToLimitUnit(cal, i);
    if (std::isnan(u) || (std::isfinite(c.value) && u <= c.value)) continue;
    c.value = u;
    worst = i;
    c.parameter = std::string(ParameterName(i));
  }
  // Held angles (a reduced model) have no U: judged are the fitted ones; none at all fails.
  c.pass = std::isfinite(c.value) && c.value <= limit;
  c.rule = cal.budget ? "the largest; U of the uncertainty budget (type A and B), as on the certificate"
                      : "the largest; U = 2 x the fit's 1-sigma: no budget, type A alone";
  if (!c.pass && cal.budget && worst >= 0)
    if (const ParameterBudget* p = cal.budget->Find(worst))
      c.why = UncertaintyRemedy(*p, limit / ToLimitUnit(cal, worst), ToLimitUnit(cal, worst) * g.text_scale,
                                g.text_unit);
  out->push_back(c);
}

// One group's values against a tolerance around their nominal: `deviation(i)` and U in the
// tolerance's unit.
void CheckTolerance(const Calibration& cal, int first, double tolerance, DecisionRule rule,
                    const std::string& what, const std::string& unit,
                    const std::function<double(int)>& deviation, const std::function<double(int)>& u_of,
                    std::vector<LimitCheck>* out) {
  if (!std::isfinite(tolerance)) return;
  const bool guard = rule == DecisionRule::kGuardBand;
  LimitCheck c;
  c.what = what;
  c.unit = unit;
  double worst = kNaN, worst_u = kNaN;
  for (int i = first; i < first + 3; ++i) {
    if (cal.FindHeld(i) != nullptr) continue;
    const double d = std::fabs(deviation(i)), u = u_of(i);
    const double judged = guard ? d + u : d;
    if (std::isfinite(worst) && !(judged > worst)) continue;
    worst = judged;
    worst_u = u;
    c.value = d;
    c.parameter = std::string(ParameterName(i));
  }
  c.limit = guard ? tolerance - worst_u : tolerance;
  c.pass = std::isfinite(c.value) && (!guard || worst_u < tolerance) && c.value <= c.limit;
  c.rule = guard ? fmt::format("the largest; guard band: the tolerance {:g} {} narrowed by U = {}", tolerance,
                               unit, WithUnit(worst_u, unit))
                 : fmt::format("the largest; simple acceptance: within the tolerance {:g} {}", tolerance, unit);
  if (!std::isfinite(c.value))
    c.why = "no nominal value to compare with (the procedure's [sensor] is not known to this report)";
  else if (!c.pass)
    c.why = guard && worst_u >= tolerance
                ? fmt::format("U({}) = {} is as large as the tolerance {:g} {}: no value could be shown to conform",
                              c.parameter, WithUnit(worst_u, unit), tolerance, unit)
                : fmt::format("{} is {:.4g} {} from nominal, beyond {} {:.4g} {}", c.parameter, c.value, unit,
                              guard ? "the acceptance limit" : "the tolerance", c.limit, unit);
  out->push_back(c);
}

void AddFitCheck(std::vector<LimitCheck>* out, std::string what, std::string unit, double value,
                 double limit, bool at_least) {
  if (!std::isfinite(limit)) return;
  LimitCheck c;
  c.what = std::move(what);
  c.unit = std::move(unit);
  c.value = value;
  c.limit = limit;
  c.at_least = at_least;
  c.pass = std::isfinite(value) && (at_least ? value >= limit : value <= limit);
  out->push_back(c);
}

}  // namespace

double CertificateExpandedUncertainty(const Calibration& cal, int index) {
  if (cal.FindHeld(index) != nullptr) return kNaN;
  if (cal.budget)
    if (const ParameterBudget* b = cal.budget->Find(index)) return b->expanded;
  return 2.0 * cal.uncertainty.ToVector()(index);
}

std::vector<LimitCheck> CheckProcedureLimits(const ProcedureLimits& l, const ReportInputs& in,
                                             const ReportModel& m) {
  const Calibration& cal = in.calibration;
  std::vector<LimitCheck> out;
  if (l.min_captures > 0) AddFitCheck(&out, "captures used by the fit", "", m.captures_used, l.min_captures, true);
  AddFitCheck(&out, "residual RMS", "m/s^2", m.residual_rms_mps2, l.max_residual_rms_mps2, false);
  AddFitCheck(&out, "residual RMS / noise RMS", "", m.residual_rms_mps2 / m.noise_rms_mps2,
              l.max_residual_rms_noise, false);
  CheckUncertainty(cal, kBiasX, l.max_bias_U_counts, &out);
  CheckUncertainty(cal, kScaleX, l.max_scale_U_ppm, &out);
  CheckUncertainty(cal, kMisYZ, l.max_misalignment_U_rad, &out);

  const Eigen::Vector3d bias0 = in.nominal_bias_counts.value_or(Eigen::Vector3d::Constant(kNaN));
  const Eigen::Vector3d scale0 = in.nominal_scale_counts_per_mps2.value_or(Eigen::Vector3d::Constant(kNaN));
  const auto u = [&](int i) { return CertificateExpandedUncertainty(cal, i); };
  CheckTolerance(cal, kBiasX, l.bias_tolerance_counts, l.decision_rule,
                 "|bias - nominal zero-g level|", "counts",
                 [&](int i) { return cal.model.bias_counts(i) - bias0(i); }, u, &out);
  CheckTolerance(cal, kScaleX, l.scale_tolerance_percent, l.decision_rule, "|scale / nominal scale - 1|",
                 "%", [&](int i) { return 100.0 * (cal.model.scale_counts_per_mps2(i - kScaleX) / scale0(i - kScaleX) - 1.0); },
                 [&](int i) { return 100.0 * u(i) / scale0(i - kScaleX); }, &out);
  CheckTolerance(cal, kMisYZ, l.misalignment_tolerance_rad, l.decision_rule, "|misalignment|", "rad",
                 [&](int i) { return cal.model.ToVector()(i); }, u, &out);
  return out;
}

std::string UncertaintyRemedy(const ParameterBudget& p, double limit, double to_display,
                              const std::string& display_unit) {
  if (!(p.expanded > limit) || !(p.coverage_factor > 0.0)) return "";
  const double k = p.coverage_factor;
  const double target = limit / k;  // the u_c that would do
  const auto shown = [&](double v) { return WithUnit(v * to_display, display_unit); };
  std::string out = fmt::format("U({}) = {} > {}", p.name, shown(p.expanded), shown(limit));
  double u_a = 0.0;
  std::vector<const BudgetContribution*> parts;
  for (const BudgetContribution& b : p.contributions) {
    if (b.type == 'A') u_a = b.contribution;
    else if (b.contribution > 0.0) parts.push_back(&b);
  }
  if (u_a >= target)
    return out + fmt::format(": the captures' own scatter alone gives {}: more captures, or longer ones",
                             shown(k * u_a));
  std::sort(parts.begin(), parts.end(), [](const BudgetContribution* a, const BudgetContribution* b) {
    return a->contribution > b->contribution;
  });
  // The largest parts, until the rest is under half the target's square (room for them, so the
  // advice is not to make one part perfect); each of them then scaled by one factor f so that
  // the whole comes to the target.
  double rest2 = p.combined * p.combined, taken2 = 0.0;
  std::vector<const BudgetContribution*> chosen;
  for (const BudgetContribution* b : parts) {
    chosen.push_back(b);
    rest2 -= b->contribution * b->contribution;
    taken2 += b->contribution * b->contribution;
    if (rest2 < target * target / 2.0) break;
  }
  const double f = std::sqrt(std::max(0.0, target * target - rest2) / taken2);
  std::vector<std::string> said, todo;
  // The parts that matter (those chosen, and any other a third of the largest or more).
  for (const BudgetContribution* b : parts) {
    if (b->contribution < parts.front()->contribution / 3.0 &&
        std::find(chosen.begin(), chosen.end(), b) == chosen.end())
      continue;
    const BenchUnit w = BenchUnitOf(b->quantity);
    said.push_back(fmt::format("the {} (u {} {}) gives {}", b->quantity,
                               TwoDigits(b->standard_uncertainty * w.scale), w.unit, shown(k * b->contribution)));
  }
  for (const BudgetContribution* b : chosen) {
    // The table tilt enters at second order: its part goes with u^2.
    const double u_needed = b->standard_uncertainty * (b->quantity == "table tilt" ? std::sqrt(f) : f);
    todo.push_back(WhatToDo(b->quantity, u_needed));
  }
  return out + ": " + fmt::format("{}; {}", fmt::join(said, ", "), fmt::join(todo, " and ")) +
         (chosen.size() < said.size() ? ", or the like with the others" : "");
}

}  // namespace accelcal

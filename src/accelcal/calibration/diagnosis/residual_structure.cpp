#include "accelcal/calibration/diagnosis/residual_structure.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/calibration/diagnosis/effect_support.h"

namespace accelcal {
namespace {

struct Variable {
  std::string name;
  std::vector<double> values;
};

// Pearson's correlation; NaN when either series is constant.
double ResidualCorrelation(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0.0, my = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    mx += x[i] / n;
    my += y[i] / n;
  }
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  // Relative to the values' size: a series constant but for rounding is constant.
  const double scale = std::max(1e-300, mx * mx * n);
  if (!(sxx > 1e-18 * scale) || !(syy > 0.0)) return kNaN;
  return sxy / std::sqrt(sxx * syy);
}

std::vector<Variable> BenchVariables(const std::vector<FitCapture>& captures) {
  std::vector<Variable> vars;
  auto add = [&](std::string name, auto get) {
    Variable v{std::move(name), {}};
    for (size_t i = 0; i < captures.size(); ++i) v.values.push_back(get(i));
    for (double x : v.values)
      if (!std::isfinite(x)) return;
    vars.push_back(std::move(v));
  };
  double t_mean = 0.0;
  for (const FitCapture& c : captures) t_mean += c.mean_t_s / static_cast<double>(captures.size());
  add("time", [&](size_t i) { return captures[i].mean_t_s; });
  add("the square of time (a curve in time)",
      [&](size_t i) { return std::pow(captures[i].mean_t_s - t_mean, 2); });
  add("temperature", [&](size_t i) { return captures[i].mean_temp_c; });
  add("turntable or static",
      [&](size_t i) { return captures[i].kind == CaptureKind::kTurntable ? 1.0 : 0.0; });
  add("the centripetal w^2 r", [&](size_t i) {
    const double c = effects::CentripetalMps2(captures[i]);
    return std::isfinite(c) ? c : 0.0;
  });
  const std::vector<Eigen::Vector3d> d = effects::RoughDirections(captures);
  for (int j = 0; j < 3; ++j) {
    const char axis = "xyz"[j];
    add(fmt::format("{} loading (u_{}^2)", axis, axis), [&](size_t i) { return d[i](j) * d[i](j); });
    add(fmt::format("{} sign (u_{})", axis, axis), [&](size_t i) { return d[i](j); });
  }
  add("corners (u_x u_y u_z)", [&](size_t i) { return d[i].x() * d[i].y() * d[i].z(); });
  return vars;
}

}  // namespace

std::string ResidualStructure::Describe() const {
  if (strongest < 0) return {};
  const StructureFinding& f = tested[static_cast<size_t>(strongest)];
  return fmt::format("the residuals follow {} (correlation {:+.2f}, p = {:.2g} over {} variables)",
                     f.variable, f.correlation, family_p, tested.size());
}

ResidualStructure FindResidualStructure(const std::vector<FitCapture>& captures,
                                        const std::vector<double>& z) {
  ResidualStructure out;
  if (captures.size() < 5 || z.size() != captures.size()) return out;
  const double n = static_cast<double>(captures.size());
  double best_p = 1.0;
  for (const Variable& v : BenchVariables(captures)) {
    const double rho = ResidualCorrelation(v.values, z);
    if (std::isnan(rho)) continue;
    const double fisher = std::atanh(std::clamp(rho, -0.999999, 0.999999)) * std::sqrt(n - 3.0);
    const double p = std::erfc(std::fabs(fisher) / std::sqrt(2.0));
    out.tested.push_back({v.name, rho, p});
    if (out.strongest < 0 || p < best_p) {
      best_p = p;
      out.strongest = static_cast<int>(out.tested.size()) - 1;
    }
  }
  if (out.strongest >= 0) out.family_p = std::min(1.0, best_p * static_cast<double>(out.tested.size()));
  return out;
}

}  // namespace accelcal

#include "accelcal/calibration/diagnosis/evidence.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

double Correlation(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) { mx += x[i] / n; my += y[i] / n; }
  double sxy = 0, sxx = 0, syy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

// How the residuals before the effect relate to its physical variable, by capture kind.
std::string RegressorEvidence(const Effect& effect, const FitSummary& before,
                              const std::vector<FitCapture>& captures) {
  if (effect.RegressorName().empty()) return {};
  std::vector<double> x, y;
  int static_without = 0;
  double static_rms = 0.0;
  for (size_t i = 0; i < captures.size(); ++i) {
    const double v = effect.Regressor(captures[i]);
    const double r = before.residuals[i].residual_mps2;
    if (std::isfinite(v)) {
      x.push_back(v);
      y.push_back(r);
    } else if (captures[i].kind == CaptureKind::kStatic) {
      ++static_without;
      static_rms += r * r;
    }
  }
  if (x.size() < 3 || *std::max_element(x.begin(), x.end()) == *std::min_element(x.begin(), x.end()))
    return {};
  const double rho = Correlation(x, y);
  std::string out = fmt::format("the residuals before it {} with {} (correlation {:+.2f} over {} captures)",
                                rho >= 0 ? "grow" : "fall", effect.RegressorName(), rho, x.size());
  if (static_without > 0)
    out += fmt::format("; static captures, which have no {}, show an RMS of {:.4f} m/s^2",
                       effect.RegressorName(), std::sqrt(static_rms / static_without));
  return out;
}

}  // namespace

std::string Evidence(const Effect& effect, const FitSummary& before, const FitSummary& after,
                     const std::vector<FitCapture>& captures) {
  double max_static = 0.0, max_turntable = 0.0, sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (size_t i = 0; i < captures.size(); ++i) {
    const double r = before.residuals[i].residual_mps2;
    const double explained = r - after.residuals[i].residual_mps2;
    double& max = captures[i].kind == CaptureKind::kStatic ? max_static : max_turntable;
    max = std::max(max, std::fabs(explained));
    sxy += r * explained;
    sxx += explained * explained;
    syy += r * r;
  }
  const double share = syy > 0.0 ? 1.0 - (syy - 2 * sxy + sxx) / syy : 0.0;
  std::string out = std::string(effect.Story());
  if (std::string by_variable = RegressorEvidence(effect, before, captures); !by_variable.empty())
    out += ": " + by_variable;
  out += fmt::format("; adding it changes turntable residuals by up to {:.4f} m/s^2 and static ones "
                     "by up to {:.4f}, and accounts for {:.0f} % of the residual sum of squares",
                     max_turntable, max_static, 100.0 * std::clamp(share, 0.0, 1.0));
  return out;
}

std::string RunnersUp(const std::vector<CandidateScore>& scores, int best) {
  const CandidateScore& b = scores[static_cast<size_t>(best)];
  std::string out;
  for (size_t i = 0; i < scores.size(); ++i) {
    const CandidateScore& c = scores[i];
    if (static_cast<int>(i) == best || !c.skipped_reason.empty()) continue;
    const double diff = c.bic - b.bic;
    if (std::fabs(diff) < 6.0)
      out += fmt::format("; {} explains the captures almost as well (BIC {:+.1f})", c.effect, diff);
    else if (diff < 0.0 && c.loo_rms_mps2 >= 0.0)
      out += fmt::format("; {} fits these captures more closely (BIC {:+.1f}) but predicts left-out "
                         "captures worse ({:.5f} against {:.5f} m/s^2)",
                         c.effect, diff, c.loo_rms_mps2, b.loo_rms_mps2);
  }
  return out;
}

}  // namespace accelcal

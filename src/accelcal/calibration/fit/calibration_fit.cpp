#include "accelcal/calibration/fit/calibration_fit.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <fmt/core.h>

#include "accelcal/base/linear_algebra.h"
#include "accelcal/calibration/fit/determinacy.h"
#include "accelcal/calibration/fit/initial_guess.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {
namespace {

std::string AxisDirection(const Eigen::Vector3d& v) {
  return fmt::format("({:+.2f}, {:+.2f}, {:+.2f})", v.x(), v.y(), v.z());
}

std::string CheckCapture(const FitCapture& c) {
  if (c.n_samples < 2) return fmt::format("capture {} has fewer than 2 samples", c.id);
  if (!c.mean_counts.allFinite() || !c.mean_cov_counts2.allFinite())
    return fmt::format("capture {} has a non-finite mean", c.id);
  if (c.kind == CaptureKind::kTurntable &&
      !(std::isfinite(c.radius_m) && c.radius_m > 0.0 && std::isfinite(c.rpm) && c.rpm > 0.0))
    return fmt::format("turntable capture {} needs a positive radius_m and rpm", c.id);
  return {};
}

// Which misalignment angle to hold next: the one with the largest part in the undetermined
// combinations (the norm of its row in their basis); -1 when none has a real part (then a bias
// or scale is undetermined, and nothing can be held).
int NextToHold(const Determinacy& d, const std::vector<int>& held) {
  int best = -1;
  double best_weight = 0.3;  // below it the combination is mostly bias and scale
  for (int j = kMisYZ; j <= kMisZX; ++j) {
    if (std::find(held.begin(), held.end(), j) != held.end()) continue;
    double w2 = 0.0;
    for (const UndeterminedCombination& u : d.undetermined) w2 += u.direction(j) * u.direction(j);
    if (std::sqrt(w2) > best_weight) {
      best_weight = std::sqrt(w2);
      best = j;
    }
  }
  return best;
}

std::string UndeterminedText(const ResidualModel& model, const UndeterminedCombination& u) {
  return std::isfinite(u.sigma_scaled)
             ? fmt::format("{} (1-sigma {:.3g} times its scale from the captures' noise)",
                           DescribeCombination(model, u.direction), u.sigma_scaled)
             : DescribeCombination(model, u.direction);
}

// The reduced model: the misalignment angles held (at the initial guess's 0) so that the rest
// is determined, with their reasons; or the reason the set cannot be calibrated.
struct HeldDecision {
  std::vector<HeldParameter> held;
  std::string refusal;
};

HeldDecision DecideHeld(const ResidualModel& model, const std::vector<FitCapture>& captures,
                        const Eigen::VectorXd& p, const FitOptions& options) {
  HeldDecision out;
  DeterminacyOptions judge;
  judge.gravity_mps2 = options.gravity.gravity_mps2;
  judge.max_sigma_scaled = options.max_sigma_scaled;
  std::vector<std::string> combinations;
  for (;;) {
    const Determinacy d = JudgeDeterminacy(model, captures, p, judge);
    if (d.determined()) break;
    const int j = options.allow_held ? NextToHold(d, judge.held) : -1;
    if (j < 0) {
      out.refusal = fmt::format(
          "the captures cannot determine {}: a combination of them changes no capture's "
          "magnitude beyond its noise; add poses or mountings that tell them apart, e.g. "
          "tilted poses whose axis signs differ, and poses on both sides of each axis",
          UndeterminedText(model, d.undetermined.front()));
      return out;
    }
    combinations.push_back(UndeterminedText(model, d.undetermined.front()));
    judge.held.push_back(j);
    out.held.push_back({j, p(j), {}});
  }
  if (out.held.empty()) return out;
  const std::string advice =
      out.held.size() == 3
          ? "the poses say nothing of the misalignment (a magnitude fit sees it only in poses "
            "tilted between the axes); add three tilted poses with independent axis-sign "
            "patterns, e.g. up = (1,1,1), (1,1,-1), (1,-1,1), to determine them"
          : "the captures cannot separate " + combinations.front() +
                "; add tilted poses whose axis-sign patterns (the signs of xy, xz, yz) differ "
                "from those taken";
  for (HeldParameter& h : out.held)
    h.reason = fmt::format("held at {} (the axes taken as orthogonal): {}", h.value, advice);
  return out;
}

}  // namespace

std::string FitOptions::Validate() const {
  if (std::string e = gravity.Validate(); !e.empty()) return "gravity: " + e;
  if (min_captures < 6) return "min_captures must be at least 6";
  if (!(max_sigma_scaled > 0.0)) return "max_sigma_scaled must be positive";
  if (!(min_planarity_ratio >= 0.0 && min_planarity_ratio < 1.0))
    return "min_planarity_ratio must be in [0, 1)";
  return solver.Validate();
}

std::string CheckDeterminable(const std::vector<FitCapture>& captures, const FitOptions& options) {
  const int n = static_cast<int>(captures.size());
  if (n < options.min_captures)
    return fmt::format("{} usable captures; a calibration needs at least {} (six give bias and "
                       "scale, nine in general position all nine parameters)", n,
                       options.min_captures);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const FitCapture& c : captures) centre += c.mean_counts / n;
  Eigen::MatrixXd centred(n, 3);
  for (int i = 0; i < n; ++i) centred.row(i) = (captures[i].mean_counts - centre).transpose();
  const SingularValueDecomposition svd = DecomposeSvd(centred);
  Eigen::Vector3d sv = Eigen::Vector3d::Zero();  // fewer than 3 captures: the missing ones are 0
  sv.head(svd.values.size()) = svd.values;
  if (!(sv(0) > 0.0)) return "all captures have the same mean reading: the sensor never moved";
  if (sv(1) / sv(0) < options.min_planarity_ratio)
    return fmt::format("all captures lie along one line of readings (direction {} in sensor axes): "
                       "the nine parameters cannot be determined; add poses along other axes",
                       AxisDirection(svd.v.col(0)));
  if (sv(2) / sv(0) < options.min_planarity_ratio)
    return fmt::format("all captures lie near one plane of readings (its normal is {} in sensor "
                       "axes, spread ratio {:.4f}): the nine parameters cannot be determined; add "
                       "poses with a component along that normal",
                       AxisDirection(svd.v.col(2)), sv(2) / sv(0));
  return {};
}

FitSummary FitCalibration(const std::vector<FitCapture>& captures, const FitOptions& options) {
  FitSummary refused;
  refused.gravity_mps2 = options.gravity.gravity_mps2;
  refused.num_captures = static_cast<int>(captures.size());
  if (std::string e = options.Validate(); !e.empty()) {
    refused.termination = FitTermination::kInvalidInput;
    refused.message = e;
    return refused;
  }
  for (const FitCapture& c : captures) {
    if (std::string e = CheckCapture(c); !e.empty()) {
      refused.termination = FitTermination::kInvalidInput;
      refused.message = e;
      return refused;
    }
  }
  if (std::string e = CheckDeterminable(captures, options); !e.empty()) {
    refused.termination = FitTermination::kUnderdetermined;
    refused.message = e;
    return refused;
  }
  LeastSquaresOptions solver = options.solver;
  solver.gravity_mps2 = options.gravity.gravity_mps2;
  const Eigen::VectorXd initial = InitialGuess(captures, solver.gravity_mps2, nullptr);
  const BaseResidualModel model;
  const HeldDecision decision = DecideHeld(model, captures, initial, options);
  if (!decision.refusal.empty()) {
    refused.termination = FitTermination::kUnderdetermined;
    refused.message = decision.refusal;
    return refused;
  }
  solver.held.clear();
  for (const HeldParameter& h : decision.held) solver.held.push_back(h.index);
  FitSummary s = SolveWeightedLeastSquares(model, captures, initial, solver);
  s.held = decision.held;
  if (s.IsUsable()) {
    if (std::string e = s.Model().Validate(); !e.empty()) {
      s.termination = FitTermination::kNumericalFailure;
      s.message = "the fit converged to an unphysical model: " + e;
    }
  }
  return s;
}

FitSummary FitCalibration(const std::vector<Capture>& captures, const FitOptions& options) {
  std::vector<FitCapture> used;
  for (const Capture& c : captures)
    if (c.used()) used.push_back(MakeFitCapture(c));
  return FitCalibration(used, options);
}

}  // namespace accelcal

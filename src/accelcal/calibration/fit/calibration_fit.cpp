#include "accelcal/calibration/fit/calibration_fit.h"

#include <cmath>

#include <Eigen/Core>
#include <fmt/core.h>

#include "accelcal/base/linear_algebra.h"
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

// The captures cannot separate some parameters when the weighted Jacobian at the initial guess
// is (numerically) rank deficient: its null direction says which ones. Empty when it is not.
std::string CheckSeparable(const ResidualModel& model, const std::vector<FitCapture>& captures,
                           const Eigen::VectorXd& p, double gravity_mps2) {
  const int np = model.NumParameters();
  Eigen::MatrixXd jac(captures.size(), np);
  Eigen::VectorXd grad(np);
  for (size_t i = 0; i < captures.size(); ++i) {
    model.Residual(p, captures[i], gravity_mps2, &grad, nullptr);
    for (int j = 0; j < np; ++j) jac(i, j) = grad(j) * model.ParameterScale(p, j);
  }
  for (int j = 0; j < np; ++j) {
    const double norm = jac.col(j).norm();
    if (!(norm > 0.0)) return fmt::format("no capture is sensitive to {}", model.ParameterLabel(j));
    jac.col(j) /= norm;
  }
  const SingularValueDecomposition svd = DecomposeSvd(jac);
  const Eigen::VectorXd& sv = svd.values;
  // Well-designed sets (six faces, three tilted poses, turntable runs) sit near 0.2; a set whose
  // tilted poses repeat an axis-sign pattern falls below 1e-3: treat that as not determinable.
  constexpr double kRankTolerance = 1e-3;
  if (sv(np - 1) > kRankTolerance * sv(0)) return {};
  const Eigen::VectorXd null = svd.v.col(np - 1);
  std::string names;
  for (int j = 0; j < np; ++j)
    if (std::fabs(null(j)) > 0.1) names += (names.empty() ? "" : ", ") + model.ParameterLabel(j);
  return fmt::format("the captures cannot separate {} (a combination of them changes no "
                     "capture's magnitude); add poses or mountings that tell them apart, e.g. "
                     "tilted poses whose axis signs differ",
                     names);
}

}  // namespace

std::string FitOptions::Validate() const {
  if (std::string e = gravity.Validate(); !e.empty()) return "gravity: " + e;
  if (min_captures < kNumBaseParameters)
    return fmt::format("min_captures must be at least {}", int(kNumBaseParameters));
  if (!(min_planarity_ratio >= 0.0 && min_planarity_ratio < 1.0))
    return "min_planarity_ratio must be in [0, 1)";
  return solver.Validate();
}

std::string CheckDeterminable(const std::vector<FitCapture>& captures, const FitOptions& options) {
  const int n = static_cast<int>(captures.size());
  if (n < options.min_captures)
    return fmt::format("{} usable captures; the nine parameters need at least {}", n,
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
  if (std::string e = CheckSeparable(model, captures, initial, solver.gravity_mps2); !e.empty()) {
    refused.termination = FitTermination::kUnderdetermined;
    refused.message = e;
    return refused;
  }
  FitSummary s = SolveWeightedLeastSquares(model, captures, initial, solver);
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

// The outcome of a calibration fit, explaining itself (after Ceres' Solver::Summary).
//
// Fields start as "never ran" values. Parameters, uncertainties and residuals are meaningful
// only when IsUsable(); otherwise `message` says why there is no calibration.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "accelcal/base/capture.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

enum class FitTermination {
  kNotRun,          // nothing was attempted
  kConverged,       // the optimum was reached; the result is usable
  kNoConvergence,   // iteration limits hit before the optimum was reached
  kNumericalFailure,// non-finite values, singular normal equations, optimizer error
  kUnderdetermined, // the captures cannot determine the parameters (refused before solving)
  kInvalidInput,    // options or captures are invalid
};

// "converged", "no_convergence", ... (as stored in files), and back.
std::string_view FitTerminationToString(FitTermination t);

struct CaptureResidual {
  int id = 0;
  double reference_mps2 = 0.0;  // |f| the capture should show
  double residual_mps2 = 0.0;   // |a^p| - |f|
  double sigma_mps2 = 0.0;      // 1-sigma of |a^p| from the capture's own noise
};

struct ParameterCorrelation {
  int first = -1;
  int second = -1;
  double rho = 0.0;  // correlation coefficient, -1..1
};

// A parameter the fit did not determine and held at a fixed value instead (a reduced model).
struct HeldParameter {
  int index = -1;       // into parameters
  double value = 0.0;   // held at, in the parameter's unit
  std::string reason;   // in words: why, and what to capture to determine it
};

// The structures of the scatter between captures (scatter_uncertainty.h), in the order tried.
enum class ScatterStructure { kIndependent, kFlicker, kRandomWalk };

// "independent", "flicker", "random_walk" (as stored in files), and back (false: unknown).
std::string_view ScatterStructureToString(ScatterStructure s);
bool ScatterStructureFromString(std::string_view text, ScatterStructure* out);
// The unit of a structure's size: "counts" or "counts/sqrt(s)".
std::string_view ScatterSizeUnit(ScatterStructure s);

// One structure fitted to a fit's residuals.
struct ScatterCandidate {
  ScatterStructure structure = ScatterStructure::kIndependent;
  double size = kNaN;            // s, B (counts) or K (counts/sqrt(s))
  double log_likelihood = kNaN;  // restricted (REML), over the error contrasts
};

// How a fit's uncertainty was taken from the scatter between its captures, when the residuals
// exceed their noise and no effect explains them (scatter_uncertainty.h).
struct ScatterModel {
  ScatterStructure structure = ScatterStructure::kIndependent;  // the one used
  double size = kNaN;              // its size, in ScatterSizeUnit(structure)
  double min_dof = kNaN;           // the smallest effective degrees of freedom over the parameters
  double ratio_to_noise = kNaN;    // the largest 1-sigma over its noise-only value, nine parameters
  std::vector<ScatterCandidate> candidates;  // every structure tried
};

struct FitSummary {
  FitTermination termination = FitTermination::kNotRun;
  std::string message;                 // one line: what happened, or why it failed
  std::vector<std::string> warnings;   // usable but worth a look (conditioning, no redundancy, ...)

  std::vector<std::string> parameter_labels;
  Eigen::VectorXd parameters;          // estimate, units as in ParameterUnit()
  Eigen::VectorXd uncertainty;         // 1-sigma, same units; NaN for a held parameter
  Eigen::MatrixXd covariance;
  double uncertainty_scale = 1.0;      // sqrt(max(1, chi2/dof)) applied to the covariance's sigmas
  // Set when the uncertainty comes from the scatter between the captures instead (then
  // uncertainty_scale is 1): scatter_uncertainty.h.
  std::optional<ScatterModel> scatter;
  // Effective degrees of freedom of each parameter's 1-sigma (same indices); empty: those of the
  // fit (dof when uncertainty_scale > 1, else infinite).
  Eigen::VectorXd uncertainty_dof;
  std::vector<HeldParameter> held;     // not fitted (empty: all were)

  std::vector<CaptureResidual> residuals;  // one per capture used, in input order
  int num_captures = 0;
  int dof = -1;                        // captures - fitted parameters
  double chi2 = -1.0;                  // sum (r/sigma)^2
  double residual_rms_mps2 = -1.0;
  double residual_max_abs_mps2 = -1.0;
  double gravity_mps2 = 0.0;

  double condition_number = -1.0;      // of the column-equilibrated weighted Jacobian
  ParameterCorrelation most_correlated;
  int optimizer_evaluations = -1;
  std::string optimizer_result;        // NLopt's result code, in words
  int gauss_newton_iterations = -1;

  bool IsUsable() const { return termination == FitTermination::kConverged; }
  // Parameter i was held, not fitted.
  bool IsHeld(int i) const;
  // The held parameter i; nullptr when it was fitted.
  const HeldParameter* FindHeld(int i) const;
  double Chi2PerDof() const { return dof > 0 ? chi2 / dof : -1.0; }
  // The nine base parameters as a model (valid when IsUsable()).
  SensorModel Model() const;
  // One line, for a status bar.
  std::string BriefReport() const;
  // Several lines: parameters with uncertainties, residual statistics, conditioning, warnings.
  std::string FullReport() const;
};

}  // namespace accelcal

// The rank decision: which combinations of a model's parameters a set of captures determines,
// judged against the captures' own noise and the parameters' natural sizes, not against a bare
// relative tolerance (which refused well-conditioned sets at random).
//
// Let J be the Jacobian of the weighted residuals r_i / sigma_i (sigma_i from the capture's own
// noise, least_squares.h) with respect to the free parameters measured in their scaled units
// (ResidualModel::ParameterScale: one unit moves a magnitude by about 1e-3 m/s^2; for the base
// model 1e-3 m/s^2 of bias, a relative 1e-3 of scale, 1 mrad of angle). Its SVD J = U S V^T
// gives, for each right singular vector v_j, the 1-sigma of that combination from the noise
// alone: 1 / s_j scaled units. A combination is undetermined when
//   - 1 / s_j > max_sigma_scaled (default 100: a 1-sigma beyond 0.1 m/s^2 of bias, 10 % of
//     scale or 0.1 rad of angle, where a linearized uncertainty means nothing and the data say
//     nothing useful about it), or
//   - s_j < 1e-10 s_max (numerically singular: no covariance can be computed).
// A set with fewer captures than free parameters always has such combinations (s_j = 0).
// What is undetermined is named by the parameters that make up the combination.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {

struct DeterminacyOptions {
  double gravity_mps2 = 9.80665;    // m/s^2
  double max_sigma_scaled = 100.0;  // scaled units (see the header comment); > 0
  double min_relative_singular_value = 1e-10;
  std::vector<int> held;            // parameters held (not judged), indices into p
};

struct UndeterminedCombination {
  Eigen::VectorXd direction;  // unit, in scaled units, over all of p (held entries 0)
  double sigma_scaled = 0.0;  // its 1-sigma from the noise, scaled units; infinite if singular
};

struct Determinacy {
  std::vector<UndeterminedCombination> undetermined;  // empty: every free combination determined
  double worst_sigma_scaled = 0.0;                    // the largest 1-sigma of any combination
  bool determined() const { return undetermined.empty(); }
};

// The decision at parameters p (the initial guess, or a solution).
Determinacy JudgeDeterminacy(const ResidualModel& model, const std::vector<FitCapture>& captures,
                             const Eigen::VectorXd& p, const DeterminacyOptions& options);

// "a_yz, a_zx (0.71 a_yz + 0.70 a_zx)": the parameters with a weight of 0.1 or more in the
// combination, then the combination itself.
std::string DescribeCombination(const ResidualModel& model, const Eigen::VectorXd& direction);

}  // namespace accelcal

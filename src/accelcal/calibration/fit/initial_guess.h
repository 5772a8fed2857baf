// A sound starting point for the nine parameters, from the capture means alone.
//
// Ignoring misalignment, |K^-1 (m - b)|^2 = f^2 for every capture is an axis-aligned
// ellipsoid through the means: sum_j A_j m_j^2 - 2 B_j m_j + C = f^2 with A_j = 1/k_j^2,
// B_j = b_j / k_j^2, and C free. That is linear in (A, B, C), so a small least-squares solve
// gives k_j = 1/sqrt(A_j), b_j = B_j / A_j for any mix of static and turntable captures.
// When that fails (A_j <= 0 from a poor spread), each axis falls back to the midpoint of its
// extreme means for the bias and half their spread over the reference for the scale.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/calibration/fit/fit_capture.h"

namespace accelcal {

// The 9-vector in ParameterIndex order; `how` (when not null) says which method was used.
Eigen::VectorXd InitialGuess(const std::vector<FitCapture>& captures, double gravity_mps2,
                             std::string* how);

}  // namespace accelcal

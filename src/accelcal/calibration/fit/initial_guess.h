// A sound starting point for the nine parameters, from the capture means alone.
//
// Ignoring misalignment, |K^-1 (m - b)|^2 = f^2 for every capture is an axis-aligned
// ellipsoid through the means. Three candidates, the one whose magnitudes fit the references
// best is taken:
//  1. Over the static captures (six or more): the quadric sum_j A_j m_j^2 - 2 B_j m_j + D = 0
//     through their means (homogeneous: the smallest singular vector), centre c_j = B_j / A_j,
//     its size G = sum_j B_j c_j - D set to gravity: k_j = sqrt(G / A_j) / g, b_j = c_j.
//  2. Over all captures (seven or more): sum_j A_j m_j^2 - 2 B_j m_j + C = f^2, linear in
//     (A, B, C) with C free: k_j = 1/sqrt(A_j), b_j = B_j / A_j. Needs references that differ
//     (turntable runs): with one reference, A, B and C - f^2 can be scaled together and still
//     fit, and the solution is noise (static sets were refused at random when this was the
//     only guess).
//  3. Each axis's bias at the midpoint of its extreme means, its scale half their spread over
//     the largest reference.
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

// The calibration fit of the seed's nine-parameter model (sensor_model.h) over a set of
// captures: checks that the set can determine the parameters, builds the initial guess, solves
// (least_squares.h) and returns a FitSummary that says whether the result is usable.
//
//   minimize  sum_i ( (|T K^-1 (mean_i - b)| - |f_i|) / sigma_i )^2
//   |f_i| = g (static), sqrt(g^2 + (w^2 r)^2) (turntable, w = rpm 2 pi / 60)
#pragma once

#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/calibration/fit/fit_summary.h"
#include "accelcal/calibration/fit/least_squares.h"
#include "accelcal/base/gravity.h"

namespace accelcal {

struct FitOptions {
  GravitySpec gravity;          // local gravity and where it came from
  int min_captures = 9;         // at least one per parameter; the seed plans 18
  // Refuse when the capture means lie this close to one plane: the smallest over the largest
  // singular value of the centred means (0.02 ~ all "up" directions within ~1 deg of a plane).
  double min_planarity_ratio = 0.02;
  LeastSquaresOptions solver;   // its gravity_mps2 is overwritten with gravity.gravity_mps2

  std::string Validate() const;
};

// Fits the captures with used() == true. Never throws for bad data: a set that cannot be
// fitted comes back with termination kUnderdetermined / kInvalidInput and the reason.
FitSummary FitCalibration(const std::vector<Capture>& captures, const FitOptions& options);
FitSummary FitCalibration(const std::vector<FitCapture>& captures, const FitOptions& options);

// Empty when the set can determine the nine parameters; else the reason, in words.
std::string CheckDeterminable(const std::vector<FitCapture>& captures, const FitOptions& options);

}  // namespace accelcal

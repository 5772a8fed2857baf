// The calibration fit of the seed's nine-parameter model (sensor_model.h) over a set of
// captures: checks that the set can be calibrated, builds the initial guess, decides which
// parameters the captures determine (determinacy.h), solves (least_squares.h) and returns a
// FitSummary that says whether the result is usable.
//
// Reduced models instead of refusals: misalignment angles the captures do not determine (six
// faces say nothing of them; two tilted poses with one axis-sign pattern cannot separate
// them) are held at 0, one at a time, the one with the largest part in the undetermined
// combinations first, until the rest is determined; the summary lists them with the reason and
// what to capture. Refused: fewer than min_captures, readings along one line or near one
// plane, and any undetermined combination of biases and scales (no prior value to hold them at).
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
  // Fewest usable captures: six (the six faces) determine bias and scale with the misalignments
  // held; nine or more in general position determine all nine. The seed plans 18.
  int min_captures = 6;
  // Refuse when the capture means lie this close to one plane: the smallest over the largest
  // singular value of the centred means (0.02 ~ all "up" directions within ~1 deg of a plane).
  double min_planarity_ratio = 0.02;
  // The rank decision: a combination whose 1-sigma from the captures' noise exceeds this many
  // scaled units is undetermined (determinacy.h; 100 = 0.1 rad of angle, 10 % of scale).
  double max_sigma_scaled = 100.0;
  // Hold undetermined misalignment angles at 0 (a reduced model); false: refuse instead.
  bool allow_held = true;
  LeastSquaresOptions solver;   // its gravity_mps2 is overwritten with gravity.gravity_mps2;
                                // its held list is decided by the fit

  std::string Validate() const;
};

// Fits the captures with used() == true. Never throws for bad data: a set that cannot be
// fitted comes back with termination kUnderdetermined / kInvalidInput and the reason.
FitSummary FitCalibration(const std::vector<Capture>& captures, const FitOptions& options);
FitSummary FitCalibration(const std::vector<FitCapture>& captures, const FitOptions& options);

// Empty when the set can be calibrated (enough captures, not along one line or in one plane);
// else the reason, in words. Which parameters it determines is decided by FitCalibration.
std::string CheckDeterminable(const std::vector<FitCapture>& captures, const FitOptions& options);

}  // namespace accelcal

// Explanations outside the library that an effect must beat before it is adopted (diagnosis.h,
// step 3). An effect of the library can fit captures whose real cause it is not: a bias that
// shifts while the table turns looks like a drift or a warm-up when every turntable run follows
// every static pose; a scale that differs between positive and negative inputs bends like a
// quadratic term. Each rival is a generic structure with the same number of parameters as the
// effects it mimics, fitted with the same base model, and challenges the effects that correct at
// its stage (effect.h CorrectionStage); when one explains the captures about as well as the
// candidate, these captures cannot name the candidate, and the diagnosis says so and what to
// capture to separate the two, rather than adopt a plausible wrong effect.
//
// Measured on the independent physics bench (tests/physics/README.md): a bias that jumps once
// mid-session, outside the library, is also no longer blamed on a library effect with these
// two rivals (0 of 50 seeds); a third rival, the jump itself scanned over the capture times,
// was tried and dropped: it mimicked real drifts and warm-ups on the project's virtual bench.
//
// The rivals are never adopted: they are not effects the program corrects, only the reason an
// effect is not named.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/calibration/fit/fit_capture.h"

namespace accelcal {

struct RivalExplanation {
  std::unique_ptr<Effect> effect;  // fitted like an effect; Name() as below
  // Parameters chosen by a scan before the fit (none of the present rivals has one): each counts
  // as one more parameter in the comparison, so that the best of many positions does not win by
  // luck.
  int scanned_parameters = 0;
};

// The rivals that `captures` can identify: "turntable_bias_shift" (a bias that differs between
// turntable and static captures, stage 0 like the temperature bias and the drift) and
// "scale_asymmetry" (per axis, a scale for negative inputs that differs from the positive one,
// stage 2 like the nonlinearities and the cross-axis coupling).
std::vector<RivalExplanation> RivalExplanations(const std::vector<FitCapture>& captures);

// The rival of that name (a static object, never freed); nullptr for a name that is not a rival.
const Effect* FindRival(std::string_view name);

// The rival's cause in plain words, and what to capture to tell it from an effect of the
// library; empty for a name that is not a rival.
std::string RivalStory(const std::string& name);
std::string RivalCapturePlan(const std::string& name);

}  // namespace accelcal

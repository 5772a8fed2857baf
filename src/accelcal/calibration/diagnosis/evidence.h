// The diagnosis's evidence in words (diagnosis.h): why an adopted effect is the one, and which
// other candidates came close. Private to the diagnosis.
#pragma once

#include <string>
#include <vector>

#include "accelcal/calibration/diagnosis/diagnosis.h"

namespace accelcal {

// Where the adopted effect changed the residuals (by capture kind, and how much of the residual
// sum of squares it accounts for) and how the residuals before it follow its physical variable.
std::string Evidence(const Effect& effect, const FitSummary& before, const FitSummary& after,
                     const std::vector<FitCapture>& captures);

// Other candidates worth naming beside the adopted one (scores[best]): those within 6 of its BIC
// (closer than "strong" evidence on the Kass & Raftery scale), and those that fit these captures
// more closely by BIC but predicted the left-out captures worse. Empty or "; ..." clauses.
std::string RunnersUp(const std::vector<CandidateScore>& scores, int best);

}  // namespace accelcal

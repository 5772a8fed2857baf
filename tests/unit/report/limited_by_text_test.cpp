// The certificate's "limited by" (report/limited_by_text.h): which uncertainty dominates each
// parameter, grouped, and what limits the calibration beyond the captures' noise.
#include <string>

#include <gtest/gtest.h>

#include "accelcal/report/limited_by_text.h"

namespace accelcal {
namespace {

ParameterBudget Budget(int index, const std::string& name, double type_a, double radius) {
  ParameterBudget p;
  p.index = index;
  p.name = name;
  p.contributions.push_back({"fit (type A)", 'A', type_a, "counts", 1.0, type_a, kNaN, ""});
  p.contributions.push_back({"radius", 'B', 0.0005, "m", radius / 0.0005, radius, kNaN, ""});
  return p;
}

TEST(LimitedBy, EachParameterByItsLargestContributionGrouped) {
  Calibration cal;
  // emplace, not `= UncertaintyBudget{}`: GCC 12 at -O1 under the sanitizers sees the optional's
  // assigning branch (never taken: it is empty) and fails the build (-Wmaybe-uninitialized).
  cal.budget.emplace();
  cal.budget->parameters = {Budget(0, "bias_x", 0.04, 0.01), Budget(1, "bias_y", 0.05, 0.01),
                            Budget(3, "scale_x", 0.001, 0.02), Budget(6, "a_yz", 1e-4, 1e-5)};
  EXPECT_EQ(LimitedByStatement(cal),
            "The uncertainty of the offsets (bias_x and bias_y) and misalignment (a_yz) is limited by the "
            "captures' noise (type A); that of the scale (scale_x) by the radius (type B). Nothing limits "
            "the calibration beyond the captures' noise.");
  // Scatter-limited, and a limit beyond the noise.
  cal.fit.scatter = ScatterModel{};
  cal.limited_by.push_back({"settling", "limited by captures taken while the sensor was still settling"});
  const std::string said = LimitedByStatement(cal);
  EXPECT_NE(said.find("is limited by the scatter between the captures beyond their noise (type A)"), std::string::npos) << said;
  EXPECT_NE(said.find("Beyond the captures' noise, the calibration is limited by captures taken while the sensor "
                      "was still settling."), std::string::npos) << said;
}

TEST(LimitedBy, WithoutABudgetTheFitAlone) {
  Calibration cal;
  EXPECT_EQ(LimitedByStatement(cal), "The uncertainty is that of the fit alone, from the captures' noise. Nothing "
                                     "limits the calibration beyond the captures' noise.");
}

}  // namespace
}  // namespace accelcal

// [target] in a procedure file: read, turned into the planner's units, and refused when looser
// than [limits].
#include <string>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/session/procedure.h"

namespace accelcal::procedure_target_test {
namespace {

std::string ProcedureText(const std::string& target, const std::string& limits = "") {
  return "title = \"t\"\n[sensor]\nrange_g = 6\nnominal_scale_counts_per_mps2 = 34.8\n"
         "nominal_bias_counts = 2048\n" +
         limits + target +
         "\n[[step]]\nid = \"pose_pz\"\nkind = \"static\"\nup = [0, 0, 1]\npose = \"+z up\"\n";
}

TEST(ProcedureTarget, ReadAndTurnedIntoThePlannersUnits) {
  const Procedure p = ParseProcedure(
      ProcedureText("[target]\nbias_mg = 1.0\nscale_ppm = 200\nmisalignment_mrad = 0.5\n"
                    "max_capture_s = 45\npose_handling_s = 15\nmounting_s = 90\n"),
      "t.toml");
  ASSERT_TRUE(p.target.Any());
  EXPECT_DOUBLE_EQ(p.target.max_capture_s, 45.0);
  EXPECT_DOUBLE_EQ(p.target.pose_handling_s, 15.0);
  EXPECT_DOUBLE_EQ(p.target.mounting_s, 90.0);
  const UncertaintyTarget t = ToUncertaintyTarget(p.target, p.nominal);
  EXPECT_NEAR(t.bias_counts, 1e-3 * 9.80665 * 34.8, 1e-12);  // 0.341 counts
  EXPECT_DOUBLE_EQ(t.scale_relative, 200e-6);
  EXPECT_DOUBLE_EQ(t.misalignment_rad, 0.5e-3);
  EXPECT_NEAR(t.ForParameter(kScaleY, p.nominal), 200e-6 * 34.8, 1e-15);
}

TEST(ProcedureTarget, AbsentMeansNone) {
  const Procedure p = ParseProcedure(ProcedureText(""), "t.toml");
  EXPECT_FALSE(p.target.Any());
  EXPECT_TRUE(ToUncertaintyTarget(p.target, p.nominal).Empty());
}

TEST(ProcedureTarget, LooserThanTheLimitsIsRefusedAtItsKey) {
  const std::string limits = "[limits]\nmax_scale_U_ppm = 100\nmax_bias_U_counts = 4\n";
  try {
    ParseProcedure(ProcedureText("[target]\nbias_mg = 1.0\nscale_ppm = 200\n", limits), "t.toml");
    FAIL() << "a scale target of U = 200 ppm against a U limit of 100 ppm was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("t.toml:"), std::string::npos) << what;
    EXPECT_NE(what.find("target.scale_ppm"), std::string::npos) << what;
    EXPECT_NE(what.find("above [limits] max_scale_U_ppm = 100"), std::string::npos) << what;
  }
  // A limit in the first format's 1-sigma key is read as U = 2 x it: 50 ppm is U = 100 ppm.
  EXPECT_THROW(ParseProcedure(ProcedureText("[target]\nscale_ppm = 200\n", "[limits]\nmax_scale_sigma_ppm = 50\n"),
                              "t.toml"),
               InputError);
  // Within: accepted.
  EXPECT_NO_THROW(ParseProcedure(ProcedureText("[target]\nscale_ppm = 100\n", limits), "t.toml"));
  // Negative or zero: refused as any number out of range.
  EXPECT_THROW(ParseProcedure(ProcedureText("[target]\nbias_mg = 0\n"), "t.toml"), InputError);
}

}  // namespace
}  // namespace accelcal::procedure_target_test

// One truth on the certificate (issue 27): the verdict decided on the U the certificate prints,
// the decision rule the procedure states, the dominant part of U and what would bring it under
// a limit, placeholder equipment and the gravity/turntable ambiguity.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/report/limit_checks.h"
#include "accelcal/report/report_model.h"
#include "accelcal/report/report_text.h"
#include "bench_calibration.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::BenchInputs;
using testing::Contains;
using testing::ProcedureWithEquipment;

ProcedureLimits SeedLimits() {
  return LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml").limits;
}

// The shipped procedure's example equipment: the radius read to 0.5 mm, the speed to 0.2 %.
std::vector<EquipmentItem> ExampleEquipment() {
  return LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml").equipment;
}

// What a good lab has: each item identified, radius and speed verified by calibrated instruments.
std::vector<EquipmentItem> GoodLab() {
  return ProcedureWithEquipment(
             "[equipment.ruler]\nid = \"RUL-7\"\nu_radius_mm = 0.03\ncalibration = \"C-2291\"\n"
             "[equipment.turntable]\nid = \"TT-1\"\nu_speed_percent = 0.02\ncalibration = \"T-118\"\n"
             "[equipment.level]\nid = \"LVL-2\"\nu_tilt_deg = 0.05\n"
             "[equipment.prism]\nid = \"PR-1\"\nu_squareness_deg = 0.1\n")
      .equipment;
}

// The largest U of a group, in the limit's unit, straight from the budget (independent of the
// checks' code): biases in counts, scales in ppm of the scale, misalignments in rad.
double LargestU(const Calibration& cal, int first) {
  double largest = 0.0;
  for (int i = first; i < first + 3; ++i) {
    const ParameterBudget* p = cal.budget->Find(i);
    const double per = first == kScaleX ? 1e6 / p->value : 1.0;
    largest = std::max(largest, p->expanded * per);
  }
  return largest;
}

const LimitCheck& CheckOn(const ReportModel& m, const std::string& what) {
  for (const LimitCheck& c : m.checks)
    if (c.what == what) return c;
  ADD_FAILURE() << "no check " << what;
  static const LimitCheck none;
  return none;
}

// Reproduces item 1: the default virtual bench passed "largest misalignment 1-sigma 0.0003 <=
// 0.005" while the same certificate's budget gave U(a_zy) = 15 mrad: the radius's 0.5 mm.
TEST(Verdict, IsDecidedOnTheUTheCertificatePrints) {
  ReportInputs in = BenchInputs(ExampleEquipment());
  in.limits = SeedLimits();
  const ReportModel m = BuildReportModel(in);
  const Calibration& cal = in.calibration;
  ASSERT_TRUE(cal.budget.has_value());
  EXPECT_EQ(m.verdict, Verdict::kFail);
  const LimitCheck& mis = CheckOn(m, "misalignment U (k = 2)");
  EXPECT_DOUBLE_EQ(mis.value, LargestU(cal, kMisYZ));
  EXPECT_GT(mis.value, 0.005);
  EXPECT_FALSE(mis.pass);
  EXPECT_TRUE(mis.on_uncertainty);
  EXPECT_EQ(mis.parameter, "a_zy");
  // The dominant part named, with the uncertainty that would bring U under 5 mrad.
  EXPECT_TRUE(Contains(mis.why, "U(a_zy) = ")) << mis.why;
  EXPECT_TRUE(Contains(mis.why, "the radius (u 0.50 mm) gives")) << mis.why;
  EXPECT_TRUE(Contains(mis.why, "measure the radius to ")) << mis.why;
  // The certificate says so, and never "Conforms".
  EXPECT_TRUE(Contains(m.certificate.conformity, "cannot show conformity: U(a_zy)")) << m.certificate.conformity;
  EXPECT_FALSE(Contains(RenderReportText(m), "Conforms:"));
  // The equipment's examples are named too (a FAIL says what failed; the list of what is
  // missing stays in the completeness section).
  EXPECT_TRUE(Contains(m.incomplete.front(), "equipment not identified: ruler RUL-01 (example)"))
      << m.incomplete.front();
}

// The demo on the virtual bench, with what a good lab has: PASS, and every limit on U agrees
// with the budget's U.
TEST(Verdict, AGoodLabPassesAndEveryLimitAgreesWithTheBudget) {
  ReportInputs in = BenchInputs(GoodLab(), GravitySpec::Given(9.80665, 2e-5));
  in.limits = SeedLimits();
  const ReportModel m = BuildReportModel(in);
  EXPECT_EQ(m.verdict, Verdict::kPass) << RenderReportText(m);
  EXPECT_TRUE(m.incomplete.empty());
  const Calibration& cal = in.calibration;
  EXPECT_DOUBLE_EQ(CheckOn(m, "bias U (k = 2)").value, LargestU(cal, kBiasX));
  EXPECT_NEAR(CheckOn(m, "scale U (k = 2)").value, LargestU(cal, kScaleX), 1e-9);
  EXPECT_DOUBLE_EQ(CheckOn(m, "misalignment U (k = 2)").value, LargestU(cal, kMisYZ));
  for (const LimitCheck& c : m.checks) EXPECT_TRUE(c.pass) << c.what;
  // Each parameter's U in the model is the certificate's.
  for (int i = 0; i < kNumBaseParameters; ++i)
    EXPECT_DOUBLE_EQ(m.parameters[static_cast<size_t>(i)].expanded, cal.budget->Find(i)->expanded);
}

// A synthetic budget: type A 1, radius 3 (u 0.5 mm), speed 2 (u 0.2 %), all in the parameter's
// unit; k = 2: U = 2 sqrt(14) = 7.48.
ParameterBudget SyntheticBudget() {
  ParameterBudget p;
  p.index = kMisZY;
  p.name = "a_zy";
  p.unit = "rad";
  p.contributions = {{"fit (type A)", 'A', 1.0, "rad", 1.0, 1.0, kNaN, ""},
                     {"radius", 'B', 0.0005, "m", 6000.0, 3.0, kNaN, ""},
                     {"turntable speed", 'B', 0.002, "1", 1000.0, 2.0, kNaN, ""}};
  p.combined = std::sqrt(14.0);
  p.coverage_factor = 2.0;
  p.expanded = 2.0 * std::sqrt(14.0);
  return p;
}

TEST(Verdict, TheRemedyBringsUUnderTheLimit) {
  // Limit 5: u_c must come to 2.5 (6.25 squared). Taken are the largest parts until the rest is
  // under half of that: without the radius 5 is left, without the speed too 1. Both scaled by
  // f: 1 + 13 f^2 = 6.25, f = 0.6355: the radius to 0.318 mm, the speed to 0.127 %.
  const std::string why = UncertaintyRemedy(SyntheticBudget(), 5.0, 1.0, "x");
  EXPECT_TRUE(Contains(why, "U(a_zy) = 7.5 x > 5.0 x")) << why;
  EXPECT_TRUE(Contains(why, "the radius (u 0.50 mm) gives 6.0 x")) << why;
  EXPECT_TRUE(Contains(why, "the turntable speed (u 0.20 %) gives 4.0 x")) << why;
  EXPECT_TRUE(Contains(why, "measure the radius to 0.31 mm or better and check the turntable's speed to 0.12 % "
                            "or better")) << why;
  // Limit 7 (12.25): without the radius 5 is left, under half: the radius alone, f = 0.8975.
  const std::string radius_only = UncertaintyRemedy(SyntheticBudget(), 7.0, 1.0, "x");
  EXPECT_TRUE(Contains(radius_only, "measure the radius to 0.44 mm or better")) << radius_only;
  EXPECT_FALSE(Contains(radius_only, "check the turntable's speed")) << radius_only;
  // Limit 3 (u_c 1.5): both, each scaled by f = sqrt(2.25 - 1) / sqrt(13) = 0.31.
  const std::string both = UncertaintyRemedy(SyntheticBudget(), 3.0, 1.0, "x");
  EXPECT_TRUE(Contains(both, "measure the radius to 0.15 mm or better and check the turntable's speed to "
                             "0.062 % or better")) << both;
  // Limit 2: the captures' own scatter (u 1, U 2) is already at it.
  EXPECT_TRUE(Contains(UncertaintyRemedy(SyntheticBudget(), 2.0, 1.0, "x"), "the captures' own scatter alone"));
  EXPECT_EQ(UncertaintyRemedy(SyntheticBudget(), 8.0, 1.0, "x"), "");
}

// The tolerance on a value: simple acceptance compares the value as found; a guard band
// narrows the tolerance by U, and a U as large as the tolerance leaves nothing to conform.
TEST(Verdict, TheProcedureChoosesTheDecisionRule) {
  ReportInputs in = BenchInputs(GoodLab(), GravitySpec::Given(9.80665, 2e-5));
  ProcedureLimits l;
  const double largest = std::fabs(in.calibration.model.bias_counts(2) - 2048.0);  // the default bench's z: 15
  const double u_z = in.calibration.budget->Find(kBiasZ)->expanded;
  l.bias_tolerance_counts = largest + u_z / 2;  // within, but not by U
  in.limits = l;
  ReportModel m = BuildReportModel(in);
  ASSERT_EQ(m.checks.size(), 1u);
  EXPECT_EQ(m.checks[0].parameter, "bias_z");
  EXPECT_TRUE(m.checks[0].pass);
  EXPECT_EQ(m.verdict, Verdict::kPass);
  EXPECT_TRUE(Contains(m.certificate.decision_rule, "simple acceptance (ILAC-G8:09/2019, 4.2.1)"));
  in.limits->decision_rule = DecisionRule::kGuardBand;
  m = BuildReportModel(in);
  EXPECT_FALSE(m.checks[0].pass);
  EXPECT_DOUBLE_EQ(m.checks[0].limit, l.bias_tolerance_counts - u_z);
  EXPECT_TRUE(Contains(m.checks[0].why, "beyond the acceptance limit")) << m.checks[0].why;
  EXPECT_EQ(m.verdict, Verdict::kFail);
  EXPECT_TRUE(Contains(m.certificate.decision_rule, "guard band (ILAC-G8:09/2019, 4.2.2"));
  in.limits->bias_tolerance_counts = u_z * 0.9;
  EXPECT_TRUE(Contains(BuildReportModel(in).checks[0].why, "no value could be shown to conform"));
}

TEST(Verdict, FirstFormatSigmaLimitsAreReadAsLimitsOnTwiceThem) {
  const std::string head = "title = \"t\"\n[sensor]\nnominal_scale_counts_per_mps2 = 34.8\nnominal_bias_counts = 2048\n";
  const std::string steps = "[[step]]\nid = \"fit\"\nkind = \"fit\"\n";
  const Procedure p = ParseProcedure(head + "[limits]\nmax_scale_sigma_ppm = 2000\nmax_misalignment_sigma_rad = 0.005\n" + steps, "p.toml");
  EXPECT_EQ(p.limits.max_scale_U_ppm, 4000.0);
  EXPECT_EQ(p.limits.max_misalignment_U_rad, 0.01);
  ASSERT_EQ(p.limits.converted.size(), 2u);
  EXPECT_EQ(p.limits.converted[0], "max_scale_sigma_ppm = 2000 (1-sigma) read as max_scale_U_ppm = 4000 (U, k = 2)");
  // The certificate says the rule.
  ReportInputs in = BenchInputs(GoodLab(), GravitySpec::Given(9.80665, 2e-5));
  in.limits = p.limits;
  EXPECT_TRUE(Contains(BuildReportModel(in).certificate.decision_rule, "read as limits on U = 2 x 1-sigma"));
  // Both forms of one limit: which one is meant is not guessed.
  EXPECT_THROW(ParseProcedure(head + "[limits]\nmax_scale_sigma_ppm = 2000\nmax_scale_U_ppm = 3000\n" + steps, "p.toml"),
               InputError);
  EXPECT_THROW(ParseProcedure(head + "[limits]\ndecision_rule = \"guarded\"\n" + steps, "p.toml"), InputError);
}

// Reproduces item 3: "id RUL-01 (example) ... state its certificate" went onto a PASS.
TEST(Verdict, PlaceholderEquipmentIsIncomplete) {
  std::vector<EquipmentItem> lab = GoodLab();
  lab[0].identification = "RUL-01 (example)";
  lab[2].identification = "";
  ReportInputs in = BenchInputs(lab, GravitySpec::Given(9.80665, 2e-5));
  in.limits = SeedLimits();
  const ReportModel m = BuildReportModel(in);
  EXPECT_EQ(m.verdict, Verdict::kIncomplete);
  ASSERT_EQ(m.incomplete.size(), 1u);
  EXPECT_TRUE(Contains(m.incomplete[0], "equipment not identified: ruler RUL-01 (example), level (no id)"))
      << m.incomplete[0];
  EXPECT_TRUE(Contains(m.certificate.conformity, "No statement of conformity")) << m.certificate.conformity;
  for (const char* placeholder : {"", "TBD", "RUL-01 (Example)", "n/a", "?"}) EXPECT_TRUE(IsPlaceholderId(placeholder));
  for (const char* id : {"RUL-01", "SN 4711", "0"}) EXPECT_FALSE(IsPlaceholderId(id));
}

TEST(Verdict, WithoutABudgetTheLimitsOnUCannotBeJudged) {
  ReportInputs in = BenchInputs(GoodLab(), GravitySpec::Given(9.80665, 2e-5));
  in.calibration.budget.reset();  // a calibration file of `accelcal fit`
  in.limits = SeedLimits();
  const ReportModel m = BuildReportModel(in);
  EXPECT_EQ(m.verdict, Verdict::kIncomplete);
  EXPECT_TRUE(Contains(m.incomplete.back(), "no uncertainty budget")) << m.incomplete.back();
  // Nor with a quantity whose uncertainty nobody stated.
  ReportInputs none = BenchInputs({}, GravitySpec::Given(9.80665, 2e-5));
  none.limits = SeedLimits();
  const ReportModel n = BuildReportModel(none);
  EXPECT_EQ(n.verdict, Verdict::kIncomplete);
  EXPECT_TRUE(Contains(n.incomplete.back(), "U lacks the uncertainty of the radius, turntable speed, table tilt"))
      << n.incomplete.back();
}

// Item 4: a speed scale on a gravity other than the standard one.
ReportInputs WithSpeedScale(const std::vector<EquipmentItem>& equipment, double scale) {
  ReportInputs in = BenchInputs(equipment, GravitySpec::FromLocation(45.0, 0.0));
  CalibrationEffect rpm;
  rpm.name = "rpm_scale";
  rpm.parameters.push_back({"rpm_scale", "1", scale, 0.00008});
  in.calibration.effects = {rpm};
  in.limits = SeedLimits();
  return in;
}

TEST(Verdict, ASpeedScaleNeedsAVerifiedTurntableWhateverTheGravity) {
  // The shipped examples: not verified, both checks named.
  std::vector<EquipmentItem> unverified = GoodLab();
  unverified[1].calibration.clear();
  ReportModel m = BuildReportModel(WithSpeedScale(unverified, 0.0013));
  EXPECT_EQ(m.verdict, Verdict::kIncomplete);
  ASSERT_FALSE(m.incomplete.empty());
  EXPECT_TRUE(Contains(m.incomplete.back(), "rpm_scale found, and the data cannot tell it from a wrong local gravity"))
      << m.incomplete.back();
  EXPECT_TRUE(Contains(m.incomplete.back(), "the turntable's speed (TT-1: no calibration stated)")) << m.incomplete.back();
  EXPECT_TRUE(Contains(m.incomplete.back(), "check the local gravity")) << m.incomplete.back();
  // Verified to 0.02 % and found 0.13 % off (the lat 45 typed at the equator): the verification
  // or the gravity is wrong.
  m = BuildReportModel(WithSpeedScale(GoodLab(), 0.0013));
  EXPECT_EQ(m.verdict, Verdict::kIncomplete);
  EXPECT_TRUE(Contains(m.incomplete.back(), "verified to u = 0.02 % (TT-1, calibration T-118) but the data finds it "
                                            "0.13 % off")) << m.incomplete.back();
  EXPECT_TRUE(Contains(m.incomplete.back(), "WGS84")) << m.incomplete.back();
  // Found within what the verification allows: PASS.
  EXPECT_EQ(BuildReportModel(WithSpeedScale(GoodLab(), 0.0002)).verdict, Verdict::kPass);
  // The note names the ambiguity on any gravity.
  EXPECT_TRUE(Contains(GravityAmbiguityNote(GravitySpec::FromLocation(45.0, 0.0), {"rpm_scale"}),
                       "a local gravity other than the one used (9.80620"));
}

// The radius's error is set against the ruler's verified u (the item the effect names:
// Effect::VerifiedBy), in the ruler's unit.
TEST(Verdict, ARadiusOffsetIsSetAgainstTheVerifiedRuler) {
  ReportInputs in = BenchInputs(GoodLab(), GravitySpec::FromLocation(45.0, 0.0));
  CalibrationEffect radius;
  radius.name = "radius_offset";
  radius.parameters.push_back({"dr", "m", 0.002, 0.0001});
  in.calibration.effects = {radius};
  in.limits = SeedLimits();
  const ReportModel m = BuildReportModel(in);
  EXPECT_EQ(m.verdict, Verdict::kIncomplete);
  ASSERT_FALSE(m.incomplete.empty());
  EXPECT_TRUE(Contains(m.incomplete.back(), "the turntable's radius is verified to u = 0.03 mm (RUL-7, calibration "
                                            "C-2291) but the data finds it 2 mm off"))
      << m.incomplete.back();
  EXPECT_TRUE(Contains(m.incomplete.back(), "check it again: a calibrated ruler")) << m.incomplete.back();
}

}  // namespace
}  // namespace accelcal

// A procedure's captures as the planner sees them and the session's plan
// (session/procedure_plan.h), on the shipped full_calibration.toml: which steps are captures
// (the step-kind table's), their forces, handling and mountings; the plan by the [target]
// against the fixed one; a target the references alone exceed left out and named; no target:
// the fixed lengths. It reads the full procedure, whose repeat poses are a kind the wizard
// defines, so it sits in the app group (its main registers the kinds, ARCHITECTURE.md).
#include "accelcal/session/procedure_plan.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/io/procedure_file.h"
#include "accelcal/session/equipment.h"

namespace accelcal::procedure_plan_test {
namespace {

constexpr double kG = 9.80665;

Procedure Full() { return LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml"); }

// A lab that measured its gravity to 2e-5 m/s^2.
ReferenceUncertainties GoodLab(const Procedure& p) { return ToReferenceUncertainties(p.equipment, 2e-5); }

const Eigen::Vector3d kDefaultNoise{1.5, 1.5, 1.7};

TEST(ProcedurePlan, CapturesAreTheStaticAndTurntableSteps) {
  const Procedure p = Full();
  const std::vector<PlannedCapture> c = PlannedCapturesOf(p, kG);
  // 9 prism poses, 9 turntable runs, the first pose taken again 3 times (twice on the stopped
  // turntable, once at the end).
  ASSERT_EQ(c.size(), 21u);
  EXPECT_EQ(c[0].id, "pose_pz");
  EXPECT_EQ(c[0].kind, CaptureKind::kStatic);
  EXPECT_TRUE(c[0].specific_force_mps2.isApprox(Eigen::Vector3d(0, 0, kG)));
  EXPECT_TRUE(c[6].specific_force_mps2.isApprox(Eigen::Vector3d(1, 1, 1).normalized() * kG));
  EXPECT_DOUBLE_EQ(c[0].handling_s, 20.0);
  EXPECT_EQ(c[0].mounting, "");
  // tt_x_050: +x radial reads -w^2 r, +z up reads g.
  EXPECT_EQ(c[9].id, "tt_x_050");
  EXPECT_EQ(c[9].kind, CaptureKind::kTurntable);
  const double w = 120.0 * 2.0 * M_PI / 60.0;
  EXPECT_NEAR(c[9].specific_force_mps2(0), -w * w * 0.05, 1e-9);
  EXPECT_NEAR(c[9].specific_force_mps2(2), kG, 1e-9);
  EXPECT_EQ(c[9].mounting, c[11].mounting);
  EXPECT_NE(c[9].mounting, c[13].mounting);
  // The repeats: the first pose's force, static captures that mount nothing.
  for (const size_t i : {12u, 16u, 20u}) {
    EXPECT_EQ(c[i].kind, CaptureKind::kStatic) << c[i].id;
    EXPECT_TRUE(c[i].specific_force_mps2.isApprox(c[0].specific_force_mps2)) << c[i].id;
    EXPECT_EQ(c[i].mounting, "") << c[i].id;
  }
  EXPECT_EQ(c[12].id, "repeat_pz_after_x");
  EXPECT_EQ(c[20].id, "repeat_pz");
  EXPECT_DOUBLE_EQ(c[9].mounting_s, 60.0);
  EXPECT_NEAR(c[9].min_capture_s, kMinTurntableRevolutions * 0.5, 1e-12);  // whole revolutions at 120 rpm
  for (const PlannedCapture& x : c) EXPECT_FALSE(x.optional) << x.id;  // every step is required
}

TEST(ProcedurePlan, FixedLengthsAreTheStepsOwnAndItsHandlingModel) {
  const Procedure p = Full();
  const SessionPlan s = PlanSession(p, kDefaultNoise, 100.0, kG, GoodLab(p), 0.0);
  // 21 captures of 10 s (the repeats take their pose's length); 21 x 20 s handling and 3
  // mountings of 60 s; the capture engine's settling (12 static captures, 9 turntable runs).
  EXPECT_DOUBLE_EQ(s.fixed.capture_s, 210.0);
  EXPECT_DOUBLE_EQ(s.fixed.handling_s, 21 * 20.0 + 3 * 60.0);
  EXPECT_DOUBLE_EQ(s.fixed.settle_s, 12 * kPlannedStaticSettleS + 9 * kPlannedTurntableSettleS);
  for (const PlannedLength& l : s.fixed.captures) EXPECT_EQ(l.samples, 1000) << l.id;
}

TEST(ProcedurePlan, ThePlanReachesTheTargetInLessBenchTime) {
  const Procedure p = Full();
  ASSERT_TRUE(p.target.Any());
  const SessionPlan s = PlanSession(p, kDefaultNoise, 100.0, kG, GoodLab(p), 0.0);
  ASSERT_TRUE(s.planned);
  EXPECT_TRUE(s.plan.feasible) << s.plan.message;
  EXPECT_LE(s.plan.TotalS(), s.fixed.TotalS());
  EXPECT_LE(s.plan.capture_s, s.fixed.capture_s);
  for (const PlannedParameter& q : s.plan.parameters) {
    const double fixed_u = s.fixed.parameters[static_cast<size_t>(q.index)].predicted_expanded;
    if (q.reachable) {
      EXPECT_LE(q.predicted_expanded, q.target_expanded) << ParameterName(q.index);
    } else {
      // Below what the references allow: within 10 % of their floor (the fixed plan's type B),
      // or within the fixed plan's U.
      const double floor_u = 2.0 * s.fixed.parameters[static_cast<size_t>(q.index)].type_b;
      EXPECT_LE(q.predicted_expanded, std::max(1.1001 * floor_u, 1.0001 * fixed_u)) << ParameterName(q.index);
    }
  }
  // --fixed-duration: the fixed plan, not the target's.
  const SessionPlan fixed = PlanSession(p, kDefaultNoise, 100.0, kG, GoodLab(p), 4.0);
  EXPECT_FALSE(fixed.planned);
  EXPECT_DOUBLE_EQ(fixed.plan.capture_s, 21 * 4.0);
  ASSERT_NE(s.For("pose_pz"), nullptr);
  EXPECT_EQ(fixed.For("pose_pz"), nullptr);
}

TEST(ProcedurePlan, ANoisierSensorNeedsLongerCaptures) {
  const Procedure p = Full();
  const SessionPlan quiet = PlanSession(p, Eigen::Vector3d::Constant(0.5), 100.0, kG, GoodLab(p), 0.0);
  const SessionPlan noisy = PlanSession(p, Eigen::Vector3d::Constant(4.0), 100.0, kG, GoodLab(p), 0.0);
  EXPECT_LT(quiet.plan.capture_s, noisy.plan.capture_s);
}

TEST(ProcedurePlan, ATargetTheReferencesAloneExceedIsNamedAndLeftOut) {
  // The standard gravity (a convention, 0.04 m/s^2 wide): about 4800 ppm U on each scale, far
  // above 200 ppm: planned near the references' floor, not at the longest captures.
  const Procedure p = Full();
  const SessionPlan s = PlanSession(p, kDefaultNoise, 100.0, kG, ToReferenceUncertainties(p.equipment, 0.04 / std::sqrt(3.0)), 0.0);
  ASSERT_FALSE(s.beyond_references.empty());
  EXPECT_NE(std::find(s.beyond_references.begin(), s.beyond_references.end(), "scale_x"), s.beyond_references.end());
  EXPECT_TRUE(s.plan.feasible) << s.plan.message;
  EXPECT_LE(s.plan.TotalS(), s.fixed.TotalS());
  EXPECT_NEAR(s.plan.parameters[kScaleX].target_expanded, 200e-6 * p.nominal.scale_counts_per_mps2(0), 1e-12);
}

TEST(ProcedurePlan, NoTargetKeepsEachStepsDuration) {
  Procedure p = Full();
  p.target = ProcedureTarget{};
  const SessionPlan s = PlanSession(p, kDefaultNoise, 100.0, kG, GoodLab(p), 0.0);
  EXPECT_FALSE(s.planned);
  EXPECT_DOUBLE_EQ(s.plan.capture_s, 210.0);
  EXPECT_EQ(s.For("pose_pz"), nullptr);
}

TEST(ProcedurePlan, NoiseDiffersBeyondAFifth) {
  EXPECT_FALSE(NoiseDiffers({1.5, 1.5, 1.7}, {1.6, 1.4, 1.8}));
  EXPECT_TRUE(NoiseDiffers({1.5, 1.5, 1.7}, {1.5, 1.5, 2.5}));
  EXPECT_TRUE(NoiseDiffers({3.0, 3.0, 3.0}, {1.5, 1.5, 1.7}));
}

}  // namespace
}  // namespace accelcal::procedure_plan_test

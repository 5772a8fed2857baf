// A turntable run whose radius has an uncertainty of its own (a fixture's board off the plate's
// reference point: the plate set down anew for each run moves it, docs/fixtures.md). The
// captures come from the independent physics bench; each run's stated radius is then off its
// true one by its own draw of N(0, u), as a board's is. The fit must weigh each run by it
// (chi2/dof near 1, residuals within what it expects), every parameter stay within its
// uncertainty of the truth, and the budget list the radii's part apart from the noise's, the two
// together the fit's covariance.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/calibration/fit/residual_model.h"
#include "accelcal/calibration/uncertainty_budget.h"
#include "physics_captures.h"

namespace accelcal::own_radius_test {
namespace {

constexpr double kOwnRadiusUM = 0.5e-3;  // 0.5 mm: a run's |f| off by ~0.07 m/s^2, ~40 x its noise

struct Drawn {
  std::vector<Capture> captures;
  Eigen::VectorXd truth = Eigen::VectorXd::Zero(kNumBaseParameters);
};

Drawn DrawSet(unsigned long long seed, bool state_u) {
  const testing::PhysicsSet set = testing::MakePhysicsSet(physgen::Effects{}, seed);
  Drawn d;
  d.captures = set.captures;
  std::mt19937_64 rng(seed + 991);
  std::normal_distribution<double> radius_error_m(0.0, kOwnRadiusUM);
  for (Capture& c : d.captures) {
    if (c.kind != CaptureKind::kTurntable) continue;
    c.radius_m += radius_error_m(rng);  // the board's true radius is not the one worked out
    if (state_u) c.radius_own_u_m = kOwnRadiusUM;
  }
  const physgen::Sensor& s = set.data.sensor;
  d.truth << s.bias_counts, s.scale_counts_per_mps2, s.a_yz_rad, s.a_zy_rad, s.a_zx_rad;
  return d;
}

FitOptions Options() {
  FitOptions o;
  o.gravity.gravity_mps2 = physgen::Bench{}.gravity_mps2;
  return o;
}

TEST(OwnRadius, UnweighedRunsScatterFarBeyondTheirNoise) {
  const FitSummary fit = FitCalibration(DrawSet(3, false).captures, Options());
  ASSERT_TRUE(fit.IsUsable()) << fit.message;
  EXPECT_GT(fit.Chi2PerDof(), 50.0);
}

TEST(OwnRadius, WeighedRunsFitAsTheirScatterSaysAndStayWithinTheirUncertainty) {
  double sum_z2 = 0.0, max_z = 0.0, sum_chi2 = 0.0;
  int n_z = 0;
  constexpr int kSets = 24;
  for (int seed = 1; seed <= kSets; ++seed) {
    const Drawn d = DrawSet(static_cast<unsigned long long>(seed), true);
    const FitSummary fit = FitCalibration(d.captures, Options());
    ASSERT_TRUE(fit.IsUsable()) << fit.message;
    sum_chi2 += fit.Chi2PerDof();
    for (int j = 0; j < kNumBaseParameters; ++j) {
      if (fit.IsHeld(j)) continue;
      const double z = (fit.parameters(j) - d.truth(j)) / std::sqrt(fit.covariance(j, j));
      sum_z2 += z * z;
      max_z = std::max(max_z, std::fabs(z));
      ++n_z;
    }
  }
  EXPECT_LT(sum_chi2 / kSets, 2.0);
  EXPECT_GT(sum_chi2 / kSets, 0.4);
  const double rms_z = std::sqrt(sum_z2 / n_z);
  EXPECT_LT(rms_z, 1.5) << "the parameters scatter beyond the uncertainty the fit claims";
  EXPECT_GT(rms_z, 0.5) << "the fit claims far more uncertainty than the parameters scatter by";
  EXPECT_LT(max_z, 4.5);
}

TEST(OwnRadius, BudgetListsTheRadiiApartAndTheTwoPartsMakeTheFitsCovariance) {
  const Drawn d = DrawSet(5, true);
  const FitSummary fit = FitCalibration(d.captures, Options());
  ASSERT_TRUE(fit.IsUsable()) << fit.message;
  std::vector<FitCapture> used;
  for (const Capture& c : d.captures) used.push_back(MakeFitCapture(c));
  ReferenceUncertainties none;  // no type B but the runs' own radii
  const UncertaintyBudget budget =
      MakeUncertaintyBudget(BaseResidualModel{}, used, fit, Options().gravity.gravity_mps2, none);
  ASSERT_EQ(budget.parameters.size(), 9u);
  for (const ParameterBudget& p : budget.parameters) {
    const BudgetContribution* type_a = nullptr;
    const BudgetContribution* radius = nullptr;
    for (const BudgetContribution& b : p.contributions) {
      if (b.quantity == "fit (type A)") type_a = &b;
      if (b.quantity == "run's own radius") radius = &b;
    }
    ASSERT_NE(type_a, nullptr);
    ASSERT_NE(radius, nullptr) << p.name;
    EXPECT_NEAR(radius->standard_uncertainty, kOwnRadiusUM, 1e-12);
    const double fit_var = fit.covariance(p.index, p.index);
    const double scale2 = fit.uncertainty_scale * fit.uncertainty_scale;
    // type A^2 + scale^2 * radius^2 = the fit's covariance (the scale applies to the noise only).
    EXPECT_NEAR(type_a->contribution * type_a->contribution +
                    scale2 * radius->contribution * radius->contribution,
                fit_var, 1e-6 * fit_var) << p.name;
    EXPECT_GT(radius->contribution, 0.0) << p.name;
  }
}

TEST(OwnRadius, ARunWithoutOneOrAStaticCaptureHasNoPart) {
  const Drawn d = DrawSet(2, false);
  const FitCapture turntable = [&] {
    for (const Capture& c : d.captures)
      if (c.kind == CaptureKind::kTurntable) return MakeFitCapture(c);
    return FitCapture{};
  }();
  Eigen::VectorXd p(kNumBaseParameters);
  p << d.truth;
  EXPECT_EQ(OwnRadiusSigma(BaseResidualModel{}, turntable, p, 9.80665), 0.0);
  FitCapture with = turntable;
  with.radius_own_u_m = 1e-3;
  // d|f|/dr = w^4 r / |f| for the seed's model (r = |a| - |f|): an independent figure.
  const double w = RpmToRadPerS(with.rpm);
  const double f = std::hypot(9.80665, w * w * with.radius_m);
  EXPECT_NEAR(OwnRadiusSigma(BaseResidualModel{}, with, p, 9.80665),
              std::pow(w, 4) * with.radius_m / f * 1e-3, 1e-6);
  FitCapture still = with;
  still.kind = CaptureKind::kStatic;
  EXPECT_EQ(OwnRadiusSigma(BaseResidualModel{}, still, p, 9.80665), 0.0);
}

}  // namespace
}  // namespace accelcal::own_radius_test

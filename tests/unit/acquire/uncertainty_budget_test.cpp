// The GUM uncertainty budget (calibration/uncertainty_budget.h) against a Monte Carlo
// propagation of the same inputs (GUM Supplement 1, JCGM 101:2008) on the virtual bench: the
// captures' means drawn from their own covariance (type A) and each reference quantity from its
// stated standard uncertainty (type B), the fit run again on every draw, and the 95.45 %
// probabilistically symmetric coverage interval of each parameter compared with the budget's
// expanded uncertainty. The Monte Carlo knows nothing of the budget's linearization: it changes
// what the fit is told (gravity, radii, speeds) and refits with FitCalibration; the table's tilt
// is drawn as what it does to a turntable run, written here from the physics (the mean specific
// force sqrt((g cos t)^2 + (w^2 r)^2), i.e. a centripetal term lowered by g^2 sin^2 t).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/base/student_t.h"
#include "accelcal/calibration/capture_screening.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/calibration/uncertainty_budget.h"

#include <Eigen/Cholesky>

namespace accelcal {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(StudentT, CoverageFactorsOfTheGumTable) {
  // JCGM 100:2008 table G.2, p = 95.45 %.
  EXPECT_NEAR(StudentTCoverageFactor(0.9545, 1.0), 13.97, 0.01);
  EXPECT_NEAR(StudentTCoverageFactor(0.9545, 2.0), 4.53, 0.01);
  EXPECT_NEAR(StudentTCoverageFactor(0.9545, 5.0), 2.65, 0.01);
  EXPECT_NEAR(StudentTCoverageFactor(0.9545, 10.0), 2.28, 0.01);
  EXPECT_NEAR(StudentTCoverageFactor(0.9545, 50.0), 2.05, 0.01);
  EXPECT_NEAR(StudentTCoverageFactor(0.9545, std::numeric_limits<double>::infinity()), 2.00, 0.001);
  // p = 95 %, 10 dof.
  EXPECT_NEAR(StudentTCoverageFactor(0.95, 10.0), 2.23, 0.01);
  EXPECT_TRUE(std::isnan(StudentTCoverageFactor(1.5, 3.0)));
  EXPECT_TRUE(std::isnan(StudentTCoverageFactor(0.95, 0.0)));
}

struct BenchFit {
  std::vector<FitCapture> used;
  FitOptions options;
  FitSummary fit;
};

BenchFit FitVirtualBench(std::uint64_t seed) {
  sim::Scenario scenario = sim::DefaultScenario();
  scenario.bench.seed = seed;
  sim::VirtualBench bench(scenario);
  std::vector<Capture> captures = bench.SimulateCaptureSet();
  ScreeningOptions screening;
  screening.adc_range = scenario.adc.Range();
  ScreenCaptures(captures, screening);
  BenchFit b;
  for (const Capture& c : captures)
    if (c.used()) b.used.push_back(MakeFitCapture(c));
  b.options.gravity = GravitySpec::Given(scenario.bench.gravity_mps2);
  b.fit = FitCalibration(b.used, b.options);
  return b;
}

// The rpm a run must be told for its reference to be what a table tilted by `tilt_rad` gives:
// (w'^2 r)^2 = (w^2 r)^2 - (g sin t)^2.
double RpmUnderTilt(double rpm, double radius_m, double g, double tilt_rad) {
  const double w = rpm * 2.0 * kPi / 60.0;
  const double centripetal = w * w * radius_m;
  const double g_side = g * std::sin(tilt_rad);
  const double lowered = std::sqrt(centripetal * centripetal - g_side * g_side);
  return std::sqrt(lowered / radius_m) * 60.0 / (2.0 * kPi);
}

// Half the width of the central 95.45 % interval of `v` (JCGM 101, 7.7).
double HalfWidth(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const auto at = [&](double q) {
    const double x = q * static_cast<double>(v.size() - 1);
    const auto i = static_cast<size_t>(x);
    const double f = x - static_cast<double>(i);
    return i + 1 < v.size() ? v[i] * (1.0 - f) + v[i + 1] * f : v[i];
  };
  return 0.5 * (at(0.5 + p / 2.0) - at(0.5 - p / 2.0));
}

TEST(UncertaintyBudget, AgreesWithMonteCarloOnTheVirtualBench) {
  const BenchFit b = FitVirtualBench(3);
  ASSERT_TRUE(b.fit.IsUsable()) << b.fit.FullReport();
  const double g = b.options.gravity.gravity_mps2;
  // Type B inputs large enough to matter next to the captures' noise: gravity from an old
  // survey, a ruler read to 0.5 mm, a turntable within 0.3 %, leveled to 0.3 deg, a prism square
  // to 0.2 deg.
  ReferenceUncertainties u;
  u.gravity_mps2 = 0.003;
  u.radius_m = 0.0005;
  u.rpm_relative = 0.003;
  u.table_tilt_rad = 0.3 * kPi / 180.0;
  u.prism_squareness_rad = 0.2 * kPi / 180.0;
  const UncertaintyBudget budget = MakeUncertaintyBudget(BaseResidualModel{}, b.used, b.fit, g, u);
  ASSERT_EQ(budget.parameters.size(), 9u);
  EXPECT_TRUE(budget.not_stated.empty());

  std::mt19937_64 rng(20260123);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Eigen::Matrix3d> chol;
  for (const FitCapture& c : b.used) chol.push_back(c.mean_cov_counts2.llt().matrixL());
  // 2000 draws in CI (~1 s; the 95.45 % half-width of 2000 draws is good to ~3 %);
  // ACCELCAL_MC_DRAWS=8000 prints the figures of docs/certificate.md.
  const char* env = std::getenv("ACCELCAL_MC_DRAWS");
  const int draws = env != nullptr ? std::max(100, std::atoi(env)) : 2000;
  std::vector<std::vector<double>> values(9);
  int failed = 0;
  for (int m = 0; m < draws; ++m) {
    FitOptions options = b.options;
    options.gravity = GravitySpec::Given(g + u.gravity_mps2 * normal(rng));
    const double radius_error = u.radius_m * normal(rng);
    const double speed_factor = 1.0 + u.rpm_relative * normal(rng);
    const double tilt = u.table_tilt_rad * normal(rng);
    std::vector<FitCapture> drawn = b.used;
    for (size_t i = 0; i < drawn.size(); ++i) {
      FitCapture& c = drawn[i];
      c.mean_counts += chol[i] * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
      if (c.kind != CaptureKind::kTurntable) continue;
      c.radius_m += radius_error;
      c.rpm = RpmUnderTilt(c.rpm * speed_factor, c.radius_m, options.gravity.gravity_mps2, tilt);
    }
    const FitSummary s = FitCalibration(drawn, options);
    if (!s.IsUsable()) {
      ++failed;
      continue;
    }
    for (int j = 0; j < 9; ++j) values[static_cast<size_t>(j)].push_back(s.parameters(j));
  }
  EXPECT_EQ(failed, 0);
  int type_b_dominated = 0;
  for (const ParameterBudget& p : budget.parameters) {
    const double mc = HalfWidth(values[static_cast<size_t>(p.index)], budget.coverage_probability);
    EXPECT_NEAR(p.expanded / mc, 1.0, 0.10) << p.name << ": budget U " << p.expanded << ", Monte Carlo " << mc;
    if (env != nullptr)
      std::printf("%-8s U %.4g  Monte Carlo %.4g  ratio %.3f  type A share %.2f\n", p.name.c_str(), p.expanded, mc,
                  p.expanded / mc, p.contributions.front().contribution / p.combined);
    if (p.contributions.front().contribution < 0.5 * p.combined) ++type_b_dominated;
  }
  // The comparison tests the type B propagation, not only the fit's covariance.
  EXPECT_GE(type_b_dominated, 3);
}

TEST(UncertaintyBudget, NamesWhatNobodyStatedAndLeavesTheSquarenessOut) {
  const BenchFit b = FitVirtualBench(4);
  ASSERT_TRUE(b.fit.IsUsable());
  ReferenceUncertainties u;
  u.gravity_mps2 = 0.0005;
  u.prism_squareness_rad = 0.01;
  const UncertaintyBudget budget =
      MakeUncertaintyBudget(BaseResidualModel{}, b.used, b.fit, b.options.gravity.gravity_mps2, u);
  EXPECT_EQ(budget.not_stated, (std::vector<std::string>{"radius", "turntable speed", "table tilt"}));
  for (const ParameterBudget& p : budget.parameters) {
    for (const BudgetContribution& c : p.contributions)
      if (c.quantity == "prism squareness") {
        EXPECT_EQ(c.contribution, 0.0);
      }
    // Only type A and gravity: infinite dof (a clean fit), k = 2.
    EXPECT_NEAR(p.coverage_factor, 2.0, 1e-3) << p.name;
    EXPECT_NEAR(p.expanded, 2.0 * p.combined, 1e-5 * p.combined);  // k(inf) at 95.45 % = 2.000003
    EXPECT_GE(p.combined, p.contributions.front().contribution);
  }
}

}  // namespace
}  // namespace accelcal

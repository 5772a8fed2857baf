// Issue 29: the numbers when the world is not white noise, on the independent physics bench
// (tests/physics): captures still settling after each change of pose, a bias that wanders (a
// random walk, flicker), and two effects the captures can barely tell apart.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "accelcal/app/calibration_pipeline.h"
#include "accelcal/calibration/near_tie.h"
#include "accelcal/calibration/settling.h"
#include "accelcal/io/calibration_file.h"
#include "physics_captures.h"
#include "test_support.h"

namespace accelcal {
namespace {

physgen::Effects Settling() {
  physgen::Effects e;
  e.settle_fraction = {0.005, 0.005, 0.005};  // the `settling` case of accelcal_physgen
  return e;
}

physgen::Effects BiasWalk() {
  physgen::Effects e;
  e.bias_walk = {0.056, 0.056, 0.056};  // the `bias_walk` case
  return e;
}

physgen::Effects Flicker() {
  physgen::Effects e;
  e.flicker = {0.5, 0.5, 0.5};  // the `flicker` case
  return e;
}

CalibrationOutcome Calibrate(const testing::PhysicsSet& set) {
  CalibrationRequest request;
  request.captures = set.captures;
  request.source_name = "physics";
  request.screening.adc_range = AdcRange{0, 4095};
  request.stability = OfflineStabilityOptions{};
  return CalibrateCaptures(std::move(request));
}

// The nine parameters' (est - truth) / sigma of `fit` against the generator's sensor.
Eigen::Matrix<double, kNumBaseParameters, 1> Z(const FitSummary& fit, const physgen::Sensor& s) {
  Eigen::Matrix<double, kNumBaseParameters, 1> truth;
  truth << s.bias_counts, s.scale_counts_per_mps2, s.a_yz_rad, s.a_zy_rad, s.a_zx_rad;
  Eigen::Matrix<double, kNumBaseParameters, 1> z;
  for (int i = 0; i < kNumBaseParameters; ++i) z(i) = (fit.parameters(i) - truth(i)) / fit.uncertainty(i);
  return z;
}

bool HasLimit(const Calibration& cal, const std::string& kind) {
  for (const UncertaintyLimit& l : cal.limited_by)
    if (l.kind == kind) return true;
  return false;
}

TEST(Settling, CapturesStillSettlingAreSeenAndTheirSettledReadingsUsed) {
  for (unsigned long long seed : {1ull, 2ull, 3ull}) {
    testing::PhysicsSet set = testing::MakePhysicsSet(Settling(), seed);
    const SettlingFinding f = HandleSettling(set.captures);
    ASSERT_TRUE(f.detected) << "seed " << seed << ": t = " << f.t_statistic.transpose()
                            << ", critical sum of t^2 " << f.critical_score;
    EXPECT_GT(f.tau_s, 5.0) << "seed " << seed;   // the generator's 15 s: a coarse figure
    EXPECT_LE(f.tau_s, 60.0) << "seed " << seed;
    int settled = 0;
    for (const Capture& c : set.captures) settled += c.settled.has_value();
    EXPECT_EQ(settled, static_cast<int>(set.captures.size()) - 1);  // all but the first
  }
}

TEST(Settling, CleanAndWanderingCapturesAreNotCalledSettling) {
  for (const physgen::Effects& e : {physgen::Effects{}, BiasWalk(), Flicker()})
    for (unsigned long long seed = 1; seed <= 6; ++seed) {
      testing::PhysicsSet set = testing::MakePhysicsSet(e, seed);
      const SettlingFinding f = HandleSettling(set.captures);
      EXPECT_FALSE(f.detected) << "seed " << seed << ": t = " << f.t_statistic.transpose()
                               << " at tau " << f.tau_s << " s, critical sum of t^2 " << f.critical_score;
      for (const Capture& c : set.captures) EXPECT_FALSE(c.settled.has_value());
    }
}

// Before: every scale 2.3-3.3 sigma off in median, scale_x beyond 3 sigma in 80 % of seeds.
TEST(Settling, ThePipelineCoversTheSettledSensorAndSaysWhy) {
  for (unsigned long long seed : {1ull, 2ull}) {
    const testing::PhysicsSet set = testing::MakePhysicsSet(Settling(), seed);
    const CalibrationOutcome o = Calibrate(set);
    ASSERT_TRUE(o.usable()) << o.diagnosis.base.message;
    EXPECT_TRUE(o.settling.detected);
    const auto z = Z(o.Fit(true), set.data.sensor);
    EXPECT_LT(z.cwiseAbs().maxCoeff(), 3.0) << "seed " << seed << ": z = " << z.transpose();
    const Calibration cal = o.MakeCalibration(true);
    ASSERT_TRUE(HasLimit(cal, "settling"));
    EXPECT_TRUE(testing::Contains(cal.limited_by.front().words, "still settling"));
    EXPECT_TRUE(testing::Contains(cal.limited_by.front().words, "Wait at least"));
  }
}

// Before: misalignments 2.5-3.7 of their stated sigmas off in rms, although scaled by
// sqrt(chi2/dof). The uncertainty now comes from a scatter model fitted to the residuals.
TEST(Scatter, AWanderingBiasGivesTheUncertaintyOfItsScatterAndSaysSo) {
  const testing::PhysicsSet set = testing::MakePhysicsSet(BiasWalk(), 1);
  const CalibrationOutcome o = Calibrate(set);
  ASSERT_TRUE(o.usable()) << o.diagnosis.base.message;
  const FitSummary& fit = o.Fit(true);
  ASSERT_TRUE(fit.scatter.has_value()) << fit.FullReport();
  EXPECT_EQ(fit.uncertainty_scale, 1.0);
  EXPECT_GT(fit.scatter->ratio_to_noise, 1.5);
  ASSERT_EQ(fit.scatter->candidates.size(), 3u);
  const Calibration cal = o.MakeCalibration(true);
  ASSERT_TRUE(HasLimit(cal, "scatter"));
  // The file keeps it.
  const Calibration back = CalibrationFromJsonText(CalibrationToJsonText(cal), "test");
  ASSERT_TRUE(back.fit.scatter.has_value());
  EXPECT_EQ(back.fit.scatter->structure, fit.scatter->structure);
  EXPECT_DOUBLE_EQ(back.fit.scatter->size, fit.scatter->size);
  EXPECT_EQ(back.fit.scatter->candidates.size(), 3u);
  ASSERT_EQ(back.limited_by.size(), cal.limited_by.size());
  EXPECT_EQ(back.limited_by.front().words, cal.limited_by.front().words);
}

TEST(Scatter, CleanCapturesKeepTheNoiseOnlyUncertainty) {
  for (unsigned long long seed : {1ull, 2ull, 3ull}) {
    const CalibrationOutcome o = Calibrate(testing::MakePhysicsSet(physgen::Effects{}, seed));
    ASSERT_TRUE(o.usable());
    EXPECT_FALSE(o.Fit(true).scatter.has_value()) << "seed " << seed;
    EXPECT_TRUE(o.MakeCalibration(true).limited_by.empty()) << "seed " << seed;
  }
}

// The near-tie: on seed 9 of the cubic case a quadratic wins by a BIC under 6 (decided by
// the left-out prediction) and moved bias_x by 4.8 sigma. Both are named now, the uncertainty
// includes the choice, and the capture that tells them apart is said.
TEST(NearTie, TwoEffectsExplainingAlikeAreBothNamedAndTheChoiceIsInTheUncertainty) {
  physgen::Effects e;
  e.cubic = {1e-4, 0.0, 0.0};  // the `cubic` case
  const testing::PhysicsSet set = testing::MakePhysicsSet(e, 9);
  const CalibrationOutcome o = Calibrate(set);
  ASSERT_TRUE(o.usable());
  ASSERT_FALSE(o.near_ties.empty()) << FormatDiagnosis(o.diagnosis);
  const NearTie& t = o.near_ties.front();
  EXPECT_NE(t.adopted, t.rival);
  EXPECT_LT(t.bic_gap, 6.0);
  EXPECT_FALSE(t.separating.empty());
  // The diagnosis says it typed, not only in words: the round that adopted one flags the other.
  bool flagged = false;
  for (const DiagnosisRound& r : o.diagnosis.rounds)
    for (const CandidateScore& c : r.candidates)
      flagged = flagged || (c.near_tie && c.effect == t.rival && r.adopted == t.adopted);
  EXPECT_TRUE(flagged) << FormatDiagnosis(o.diagnosis);
  const auto z = Z(o.Fit(true), set.data.sensor);
  EXPECT_LT(z.cwiseAbs().maxCoeff(), 3.0) << z.transpose();
  const Calibration cal = o.MakeCalibration(true);
  ASSERT_TRUE(HasLimit(cal, "near_tie"));
  const std::string words = cal.limited_by.back().words;
  EXPECT_TRUE(testing::Contains(words, t.adopted) && testing::Contains(words, t.rival)) << words;
}

}  // namespace
}  // namespace accelcal

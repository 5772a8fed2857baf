// The planner's predicted covariance against the fit's own covariance and against the scatter of
// fitted parameters, on captures from the independent physics bench (tests/physics); and the
// plan: lengths that reach a target in less time than fixed ones, a target the references forbid,
// optional poses that buy nothing.
#include "accelcal/calibration/capture_plan.h"

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/calibration/fit/calibration_fit.h"
#include "physics_bench.h"

namespace accelcal::capture_plan_test {
namespace {

constexpr double kG = 9.80665;

SensorModel ModelOf(const physgen::Sensor& s) {
  SensorModel m;
  m.bias_counts = s.bias_counts;
  m.scale_counts_per_mps2 = s.scale_counts_per_mps2;
  m.a_yz_rad = s.a_yz_rad;
  m.a_zy_rad = s.a_zy_rad;
  m.a_zx_rad = s.a_zx_rad;
  return m;
}

SensorAxis Axis(const std::string& text) { return *StringToSensorAxis(text); }

// The physics bench's plan as the planner's captures (forces written from the specs here, not
// from the generator's code).
std::vector<PlannedCapture> Planned(const std::vector<physgen::CaptureSpec>& plan) {
  std::vector<PlannedCapture> out;
  for (const physgen::CaptureSpec& spec : plan) {
    PlannedCapture c;
    c.id = spec.label;
    if (spec.kind == physgen::Kind::kStatic) {
      c.specific_force_mps2 = PlannedCapture::StaticForce(spec.up, kG);
    } else {
      c.kind = CaptureKind::kTurntable;
      c.radius_m = spec.radius_m;
      c.rpm = spec.rpm;
      c.specific_force_mps2 =
          PlannedCapture::TurntableForce(Axis(spec.radial_axis), Axis(spec.up_axis), spec.radius_m, spec.rpm, kG);
      c.mounting = spec.radial_axis + spec.up_axis;
      c.mounting_s = 60.0;
    }
    c.min_capture_s = 1.0;
    out.push_back(c);
  }
  return out;
}

std::vector<double> Lengths(const std::vector<physgen::CaptureSpec>& plan) {
  std::vector<double> d;
  for (const physgen::CaptureSpec& spec : plan) d.push_back(spec.duration_s);
  return d;
}

// The fit of one generated set (no effects; the bench's placement errors and warm-up only).
FitSummary FitSet(const physgen::Sensor& sensor, const std::vector<physgen::CaptureSpec>& plan,
                  std::mt19937_64& rng) {
  const physgen::CaptureSetData set = physgen::Generate(sensor, physgen::Effects{}, physgen::Bench{}, plan, rng);
  std::vector<Capture> captures;
  int id = 0;
  for (const physgen::CaptureData& c : set.captures) {
    Capture cap;
    cap.id = ++id;
    if (c.spec.kind == physgen::Kind::kTurntable) {
      cap.kind = CaptureKind::kTurntable;
      cap.radius_m = c.spec.radius_m;
      cap.rpm = c.spec.rpm;
      cap.up_axis = Axis(c.spec.up_axis);
    }
    for (const physgen::Sample& s : c.samples) cap.samples.push_back({s.t_s, s.raw_counts, s.temp_c});
    captures.push_back(std::move(cap));
  }
  return FitCalibration(captures, FitOptions{});
}

// Uneven lengths, so the prediction is checked where the weights differ between captures.
std::vector<physgen::CaptureSpec> UnevenSeedPlan() {
  std::vector<physgen::CaptureSpec> plan = physgen::SeedPlan(4.0, 7.0);
  for (size_t i = 0; i < plan.size(); ++i) plan[i].duration_s += static_cast<double>(i % 4);
  return plan;
}

TEST(CapturePlan, PredictedCovarianceIsTheFitsOwn) {
  const std::vector<physgen::CaptureSpec> plan = UnevenSeedPlan();
  std::mt19937_64 rng(2026);
  const physgen::Sensor sensor = physgen::DrawSensor(physgen::Sensor{}, rng);
  const FitSummary fit = FitSet(sensor, plan, rng);
  ASSERT_TRUE(fit.IsUsable()) << fit.message;
  ASSERT_TRUE(fit.held.empty());
  PlannedSensor planned{ModelOf(sensor), sensor.noise_counts, sensor.rate_hz};
  const Eigen::MatrixXd predicted = PredictCovariance(Planned(plan), Lengths(plan), planned, kG);
  ASSERT_EQ(predicted.rows(), kNumBaseParameters);
  const double scale2 = fit.uncertainty_scale * fit.uncertainty_scale;
  for (int j = 0; j < kNumBaseParameters; ++j) {
    const double ratio = std::sqrt(predicted(j, j) / (fit.covariance(j, j) / scale2));
    EXPECT_NEAR(ratio, 1.0, 0.08) << ParameterName(j);
  }
  // The correlations too (the off-diagonal terms): the scale-bias ones are the largest.
  for (int j = 0; j < kNumBaseParameters; ++j)
    for (int k = j + 1; k < kNumBaseParameters; ++k) {
      const double rho_p = predicted(j, k) / std::sqrt(predicted(j, j) * predicted(k, k));
      const double rho_f = fit.covariance(j, k) / std::sqrt(fit.covariance(j, j) * fit.covariance(k, k));
      EXPECT_NEAR(rho_p, rho_f, 0.05) << ParameterName(j) << " " << ParameterName(k);
    }
}

TEST(CapturePlan, PredictedSigmasAreTheScatterOfFittedParameters) {
  // Over 40 sets of one sensor, (fitted - true) / predicted sigma has unit variance: the
  // prediction is neither optimistic nor pessimistic.
  const std::vector<physgen::CaptureSpec> plan = UnevenSeedPlan();
  physgen::Sensor sensor;
  PlannedSensor planned{ModelOf(sensor), sensor.noise_counts, sensor.rate_hz};
  const Eigen::MatrixXd predicted = PredictCovariance(Planned(plan), Lengths(plan), planned, kG);
  ASSERT_EQ(predicted.rows(), kNumBaseParameters);
  const Eigen::VectorXd truth = ModelOf(sensor).ToVector();
  std::mt19937_64 rng(7);
  double sum_z2 = 0.0;
  int n = 0;
  for (int set = 0; set < 40; ++set) {
    const FitSummary fit = FitSet(sensor, plan, rng);
    ASSERT_TRUE(fit.IsUsable()) << fit.message;
    for (int j = 0; j < kNumBaseParameters; ++j) {
      const double z = (fit.parameters(j) - truth(j)) / std::sqrt(predicted(j, j));
      sum_z2 += z * z;
      ++n;
    }
  }
  // chi2 over 360 values (correlated within a set): mean 1, a few tenths either way at most.
  EXPECT_NEAR(sum_z2 / n, 1.0, 0.25);
}

PlannedSensor Nominal(double noise_counts) {
  PlannedSensor s;
  s.nominal.bias_counts = Eigen::Vector3d::Constant(2048.0);
  s.nominal.scale_counts_per_mps2 = Eigen::Vector3d::Constant(34.8);
  s.noise_counts = Eigen::Vector3d::Constant(noise_counts);
  s.rate_hz = 100.0;
  return s;
}

// What the fixed 10 s plan reaches: the target of the planner in the next tests.
UncertaintyTarget TargetOfFixedPlan(const std::vector<PlannedCapture>& captures, const PlannedSensor& sensor,
                                    const PlanOptions& options) {
  const std::vector<PlannedParameter> fixed =
      PredictUncertainty(captures, std::vector<double>(captures.size(), 10.0), sensor, {}, options);
  UncertaintyTarget t;
  t.bias_counts = t.scale_relative = t.misalignment_rad = 0.0;
  for (const PlannedParameter& p : fixed) {
    if (p.index <= kBiasZ) t.bias_counts = std::max(t.bias_counts, p.predicted_expanded);
    else if (p.index <= kScaleZ)
      t.scale_relative = std::max(t.scale_relative, p.predicted_expanded / sensor.nominal.scale_counts_per_mps2(0));
    else t.misalignment_rad = std::max(t.misalignment_rad, p.predicted_expanded);
  }
  return t;
}

TEST(CapturePlan, ReachesTheFixedPlansUncertaintyInLessCaptureTime) {
  const std::vector<PlannedCapture> captures = Planned(physgen::SeedPlan(10.0, 10.0));
  const PlannedSensor sensor = Nominal(1.6);
  PlanOptions options;
  options.margin = 1.0;
  const UncertaintyTarget target = TargetOfFixedPlan(captures, sensor, options);
  const CapturePlan plan = PlanCaptures(captures, sensor, target, options);
  ASSERT_TRUE(plan.feasible) << plan.message;
  EXPECT_LT(plan.capture_s, 0.8 * 180.0);  // the fixed plan's worst parameter sets the target
  std::vector<double> lengths;
  for (const PlannedLength& l : plan.captures) {
    EXPECT_TRUE(l.taken);
    EXPECT_GE(l.capture_s, 1.0);
    EXPECT_LE(l.capture_s, 60.0);
    EXPECT_EQ(l.samples, std::lround(std::ceil(l.capture_s * 100.0)));
    lengths.push_back(l.capture_s);
  }
  // Every targeted parameter within its target at the planned lengths (predicted anew).
  for (const PlannedParameter& p : PredictUncertainty(captures, lengths, sensor, target, options))
    EXPECT_LE(p.predicted_expanded, p.target_expanded * 1.0001) << ParameterName(p.index);
  // Handling: 18 captures at 20 s and three mountings at 60 s.
  EXPECT_DOUBLE_EQ(plan.handling_s, 18 * 20.0 + 3 * 60.0);
}

TEST(CapturePlan, ANoisierSensorNeedsLongerCaptures) {
  const std::vector<PlannedCapture> captures = Planned(physgen::SeedPlan(10.0, 10.0));
  PlanOptions options;
  const UncertaintyTarget target = TargetOfFixedPlan(captures, Nominal(1.6), options);
  const CapturePlan quiet = PlanCaptures(captures, Nominal(0.5), target, options);
  const CapturePlan usual = PlanCaptures(captures, Nominal(1.6), target, options);
  ASSERT_TRUE(quiet.feasible && usual.feasible);
  EXPECT_LT(quiet.capture_s, usual.capture_s);
  // Eight counts: beyond the 60 s maximum; the plan says how long it would take without it.
  const CapturePlan noisy = PlanCaptures(captures, Nominal(8.0), target, options);
  EXPECT_FALSE(noisy.feasible);
  EXPECT_EQ(noisy.message, "the target needs captures longer than the procedure's maximum");
  EXPECT_GT(noisy.unbounded_total_s, usual.TotalS());
  EXPECT_TRUE(std::isfinite(noisy.unbounded_total_s));
}

TEST(CapturePlan, ATargetBelowTheReferencesTypeBIsUnreachable) {
  const std::vector<PlannedCapture> captures = Planned(physgen::SeedPlan(10.0, 10.0));
  PlanOptions options;
  options.references.radius_m = 0.002;  // a 2 mm ruler reading: scale known to ~1 % at best
  UncertaintyTarget target;
  target.scale_relative = 200e-6;
  const CapturePlan plan = PlanCaptures(captures, Nominal(1.6), target, options);
  EXPECT_FALSE(plan.feasible);
  EXPECT_EQ(plan.message, "the reference quantities' uncertainty alone exceeds the target");
  EXPECT_TRUE(std::isnan(plan.unbounded_total_s));
  bool some_scale_unreachable = false;
  for (const PlannedParameter& p : plan.parameters)
    if (p.index >= kScaleX && p.index <= kScaleZ && !p.reachable) some_scale_unreachable = true;
  EXPECT_TRUE(some_scale_unreachable);
}

TEST(CapturePlan, OptionalPosesThatBuyNothingAreLeftOut) {
  std::vector<PlannedCapture> captures = Planned(physgen::SeedPlan(10.0, 10.0));
  // Repeats of two faces, optional: with a loose target they only cost handling.
  for (const char* id : {"+z up", "-x up"}) {
    for (const PlannedCapture& c : std::vector<PlannedCapture>(captures)) {
      if (c.id != id) continue;
      PlannedCapture again = c;
      again.id = c.id + " again";
      again.optional = true;
      captures.push_back(again);
    }
  }
  UncertaintyTarget loose;
  loose.bias_counts = 2.0;
  loose.scale_relative = 2000e-6;
  loose.misalignment_rad = 0.005;
  PlanOptions options;
  options.min_captures = 15;
  const CapturePlan plan = PlanCaptures(captures, Nominal(1.6), loose, options);
  ASSERT_TRUE(plan.feasible) << plan.message;
  EXPECT_EQ(plan.buy_nothing.size(), 2u);
  int taken = 0;
  for (const PlannedLength& l : plan.captures) {
    taken += l.taken ? 1 : 0;
    if (l.id.find("again") != std::string::npos) {
      EXPECT_FALSE(l.taken) << l.id;
    }
  }
  EXPECT_EQ(taken, 18);
  // Never below the procedure's fewest captures: all optional, 17 allowed.
  for (PlannedCapture& c : captures) c.optional = true;
  options.min_captures = 17;
  const CapturePlan tight = PlanCaptures(captures, Nominal(1.6), loose, options);
  ASSERT_TRUE(tight.feasible) << tight.message;
  int kept = 0;
  for (const PlannedLength& l : tight.captures) kept += l.taken ? 1 : 0;
  EXPECT_EQ(kept, 17);
}

TEST(CapturePlan, SixFacesDoNotDetermineMisalignment) {
  std::vector<physgen::CaptureSpec> faces = physgen::SeedPlan(10.0, 10.0);
  faces.resize(6);
  UncertaintyTarget target;
  target.misalignment_rad = 0.001;
  const CapturePlan plan = PlanCaptures(Planned(faces), Nominal(1.6), target, PlanOptions{});
  EXPECT_FALSE(plan.feasible);
  EXPECT_EQ(plan.message, "the planned captures do not determine the nine parameters");
}

}  // namespace
}  // namespace accelcal::capture_plan_test

// Physics of the virtual bench: what a perfect (noiseless) sensor on it must read.
#include "accelcal/acquire/sim/virtual_bench.h"

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "accelcal/base/error.h"

namespace accelcal::sim {
namespace {

// Half a count on every axis, through the calibration, bounds the error of a mean of identical
// quantized readings: 0.5 / 34.4 per axis, ~0.025 m/s^2 in magnitude. A little margin on top.
constexpr double kQuantizationTolMps2 = 0.03;

Scenario Noiseless() {
  Scenario s = DefaultScenario();
  s.sensor.noise_counts.setZero();
  return s;
}

Eigen::Vector3d CalibratedMean(const SensorModel& truth, const Capture& c) {
  return truth.Calibrate(ComputeStats(c.samples).mean_counts);
}

double TrueOmega(const Scenario& s, const Capture& c) {
  return RpmToRadPerS(c.rpm) * (1.0 + s.effects.rpm_scale);
}

TEST(VirtualBench, StaticCapturesFeelGravityAlongUp) {
  VirtualBench bench(Noiseless());
  const Scenario& s = bench.scenario();
  const std::vector<Capture> captures = bench.SimulateCaptureSet();
  for (std::size_t i = 0; i < captures.size(); ++i) {
    if (captures[i].kind != CaptureKind::kStatic) continue;
    SCOPED_TRACE(captures[i].label);
    const Eigen::Vector3d f = CalibratedMean(s.sensor.model, captures[i]);
    EXPECT_NEAR(f.norm(), s.bench.gravity_mps2, kQuantizationTolMps2);
    // Up to the placement error (0.5 deg std), f points along the plan's `up`.
    EXPECT_GT(f.normalized().dot(s.captures[i].up), std::cos(0.05));
  }
}

TEST(VirtualBench, TurntableCapturesFeelGravityAndCentripetal) {
  VirtualBench bench(Noiseless());
  const Scenario& s = bench.scenario();
  int checked = 0;
  for (const Capture& c : bench.SimulateCaptureSet()) {
    if (c.kind != CaptureKind::kTurntable) continue;
    SCOPED_TRACE(c.label);
    const Eigen::Vector3d f = CalibratedMean(s.sensor.model, c);
    EXPECT_NEAR(f.norm(), ReferenceMagnitudeMps2(c.kind, s.bench.gravity_mps2, c.radius_m, c.rpm),
                kQuantizationTolMps2);
    ++checked;
  }
  EXPECT_EQ(checked, 9);
}

TEST(VirtualBench, CentripetalSpecificForcePointsToTheAxis) {
  // +x radial, +z up: the sensor is accelerated inwards, so it reads -w^2 r along +x and +g on z.
  VirtualBench bench(Noiseless());
  const Scenario& s = bench.scenario();
  const std::vector<Capture> captures = bench.SimulateCaptureSet();
  const Capture& c = captures.at(11);
  ASSERT_EQ(s.captures.at(11).radial_axis, SensorAxis::kPlusX);
  const Eigen::Vector3d f = CalibratedMean(s.sensor.model, c);
  const double w = TrueOmega(s, c);
  EXPECT_NEAR(f.x(), -w * w * c.radius_m, 0.3);  // 0.3: gravity leaking through placement error
  EXPECT_NEAR(f.z(), s.bench.gravity_mps2, 0.3);
}

TEST(VirtualBench, CaptureSetFollowsThePlanAndTheSessionClock) {
  VirtualBench bench(DefaultScenario());
  const Scenario& s = bench.scenario();
  const std::vector<Capture> captures = bench.SimulateCaptureSet();
  ASSERT_EQ(captures.size(), s.captures.size());
  double start_s = 0.0;
  for (std::size_t i = 0; i < captures.size(); ++i) {
    const Capture& c = captures[i];
    EXPECT_EQ(c.id, static_cast<int>(i) + 1);
    EXPECT_EQ(c.kind, s.captures[i].kind);
    EXPECT_EQ(c.label, s.captures[i].label);
    ASSERT_EQ(c.samples.size(), 1000u);
    EXPECT_DOUBLE_EQ(c.samples.front().t_s, start_s);
    EXPECT_NEAR(c.samples.back().t_s, start_s + 9.99, 1e-9);
    EXPECT_EQ(c.samples.front().temp_c, 25.0);
    if (c.kind == CaptureKind::kStatic) {
      EXPECT_TRUE(std::isnan(c.radius_m));
      EXPECT_TRUE(std::isnan(c.rpm));
    } else {
      EXPECT_EQ(c.radius_m, s.captures[i].radius_m);
      EXPECT_EQ(c.rpm, 120.0);
    }
    for (const Sample& smp : c.samples) {
      ASSERT_EQ(smp.raw_counts, smp.raw_counts.array().round().matrix()) << "not whole counts";
    }
    start_s += 10.0 + s.bench.gap_s;
  }
}

TEST(VirtualBench, NoiseStdIsRecovered) {
  Scenario s = DefaultScenario();
  s.sensor.noise_counts = {1.5, 2.0, 3.0};
  s.captures.resize(1);
  s.captures[0].duration_s = 100.0;
  VirtualBench bench(s);
  const Eigen::Vector3d std_counts =
      ComputeStats(bench.SimulateCaptureSet()[0].samples).StdCounts();
  for (int i = 0; i < 3; ++i) {
    // Rounding to whole counts adds a uniform error of variance 1/12.
    const double expected =
        std::sqrt(s.sensor.noise_counts(i) * s.sensor.noise_counts(i) + 1.0 / 12.0);
    EXPECT_NEAR(std_counts(i), expected, 0.04 * expected) << "axis " << i;
  }
}

TEST(VirtualBench, QuadraticEffectAddsQTimesSquaredAxisForce) {
  Scenario linear = Noiseless();
  Scenario curved = linear;
  curved.effects.quadratic_counts_per_mps2_sq = {0.05, -0.04, 0.03};
  const std::vector<Capture> a = VirtualBench(linear).SimulateCaptureSet();
  const std::vector<Capture> b = VirtualBench(curved).SimulateCaptureSet();
  const SensorModel& m = linear.sensor.model;
  double largest_counts = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE(a[i].label);
    const Eigen::Vector3d mean_a = ComputeStats(a[i].samples).mean_counts;
    const Eigen::Vector3d along_axes =
        (mean_a - m.bias_counts).cwiseQuotient(m.scale_counts_per_mps2);
    const Eigen::Vector3d expected =
        curved.effects.quadratic_counts_per_mps2_sq.cwiseProduct(along_axes.cwiseAbs2());
    const Eigen::Vector3d diff = ComputeStats(b[i].samples).mean_counts - mean_a;
    // One count: each mean is within half a count of its unrounded value.
    EXPECT_LT((diff - expected).cwiseAbs().maxCoeff(), 1.0 + 1e-9) << diff.transpose();
    largest_counts = std::max(largest_counts, expected.cwiseAbs().maxCoeff());
  }
  EXPECT_GT(largest_counts, 20.0);  // the turntable runs make it plain to see
}

TEST(VirtualBench, RadiusOffsetMovesTheSensingPointOutwards) {
  Scenario s = Noiseless();
  s.effects.radius_offset_m = 0.01;
  VirtualBench bench(s);
  for (const Capture& c : bench.SimulateCaptureSet()) {
    if (c.kind != CaptureKind::kTurntable) continue;
    SCOPED_TRACE(c.label);
    const double w = TrueOmega(s, c);
    const double true_mps2 = std::hypot(s.bench.gravity_mps2, w * w * (c.radius_m + 0.01));
    const double stated_mps2 =
        ReferenceMagnitudeMps2(c.kind, s.bench.gravity_mps2, c.radius_m, c.rpm);
    const double measured_mps2 = CalibratedMean(s.sensor.model, c).norm();
    EXPECT_NEAR(measured_mps2, true_mps2, kQuantizationTolMps2);
    EXPECT_GT(measured_mps2 - stated_mps2, 0.3);
    EXPECT_EQ(c.radius_m, s.captures[static_cast<std::size_t>(c.id - 1)].radius_m);  // stated
  }
}

TEST(VirtualBench, RpmScaleSpeedsTheTableUp) {
  Scenario s = Noiseless();
  s.effects.rpm_scale = 0.02;
  VirtualBench bench(s);
  const Capture c = bench.SimulateCaptureSet().at(17);
  const double w = RpmToRadPerS(120.0) * 1.02;
  EXPECT_NEAR(CalibratedMean(s.sensor.model, c).norm(),
              std::hypot(s.bench.gravity_mps2, w * w * c.radius_m), kQuantizationTolMps2);
  EXPECT_EQ(c.rpm, 120.0);  // the stated speed
}

// Amplitude of the once-per-revolution component of `series` (least squares a + b sin + c cos).
double OncePerRevolutionAmplitude(const std::vector<double>& t_s, const std::vector<double>& series,
                                  double omega) {
  Eigen::MatrixXd a(static_cast<Eigen::Index>(t_s.size()), 3);
  Eigen::VectorXd y(static_cast<Eigen::Index>(t_s.size()));
  for (std::size_t k = 0; k < t_s.size(); ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    a.row(row) << 1.0, std::sin(omega * t_s[k]), std::cos(omega * t_s[k]);
    y(row) = series[k];
  }
  const Eigen::Vector3d coef = a.colPivHouseholderQr().solve(y);
  return std::hypot(coef(1), coef(2));
}

TEST(VirtualBench, TiltedTurntableGivesOncePerRevolutionGravity) {
  Scenario s = Noiseless();
  s.bench.placement_error_deg = 0.0;
  const double tilt_rad = 0.02;
  s.effects.turntable_tilt_rad = tilt_rad;
  s.captures = {s.captures.at(9)};  // +x radial, +z up, 0.05 m, 120 rpm
  s.captures[0].rpm = 60.0;
  VirtualBench bench(s);
  const Capture c = bench.SimulateCaptureSet().at(0);
  std::vector<double> t_s, fx, fy, fz;
  for (const Sample& smp : c.samples) {
    const Eigen::Vector3d f = s.sensor.model.Calibrate(smp.raw_counts);
    t_s.push_back(smp.t_s);
    fx.push_back(f.x());
    fy.push_back(f.y());
    fz.push_back(f.z());
  }
  const double omega = RpmToRadPerS(60.0);
  const double expected_mps2 = s.bench.gravity_mps2 * std::sin(tilt_rad);  // ~0.196 m/s^2
  EXPECT_NEAR(OncePerRevolutionAmplitude(t_s, fx, omega), expected_mps2, 0.05 * expected_mps2);
  EXPECT_NEAR(OncePerRevolutionAmplitude(t_s, fy, omega), expected_mps2, 0.05 * expected_mps2);
  EXPECT_LT(OncePerRevolutionAmplitude(t_s, fz, omega), 0.01);

  // A level table shows no such oscillation.
  s.effects.turntable_tilt_rad = 0.0;
  VirtualBench level(s);
  std::vector<double> level_x;
  const Capture level_capture = level.SimulateCaptureSet().at(0);
  for (const Sample& smp : level_capture.samples) {
    level_x.push_back(s.sensor.model.Calibrate(smp.raw_counts).x());
  }
  EXPECT_LT(OncePerRevolutionAmplitude(t_s, level_x, omega), 0.01);
}

TEST(VirtualBench, SizeEffectPutsEachAxisAtItsOwnRadius) {
  Scenario s = Noiseless();
  s.bench.placement_error_deg = 0.0;
  s.effects.size_effect_m = {0.004, 0.0, 0.0};
  VirtualBench bench(s);
  const CapturePlan& plan = s.captures.at(9);  // +x radial
  const Mounting m = bench.BeginCapture(plan, 0.0);
  const Eigen::Matrix3d f = bench.SpecificForcePerAxis(m, 1.234);
  const double w = RpmToRadPerS(plan.rpm);
  EXPECT_NEAR(f(0, 0), -w * w * (plan.radius_m + 0.004), 1e-9);  // x's proof mass, further out
  EXPECT_NEAR(f(0, 1), -w * w * plan.radius_m, 1e-9);            // y's, at the nominal point
  EXPECT_NEAR(bench.SpecificForcePlatform(m, 1.234).x(), -w * w * plan.radius_m, 1e-9);
}

TEST(VirtualBench, BiasDriftsWithSessionTime) {
  Scenario s = DefaultScenario();
  s.bench.placement_error_deg = 0.0;
  s.bench.gap_s = 990.0;
  s.effects.bias_drift_counts_per_s = {0.01, -0.02, 0.005};
  s.captures = {s.captures.at(0), s.captures.at(0)};  // the same pose twice, 1000 s apart
  VirtualBench bench(s);
  const std::vector<Capture> c = bench.SimulateCaptureSet();
  const Eigen::Vector3d diff =
      ComputeStats(c[1].samples).mean_counts - ComputeStats(c[0].samples).mean_counts;
  // Noise (1.5 counts) dithers the rounding, so the means resolve well below a count.
  EXPECT_LT((diff - s.effects.bias_drift_counts_per_s * 1000.0).cwiseAbs().maxCoeff(), 0.25)
      << diff.transpose();
}

TEST(VirtualBench, TemperatureRampAndCoefficients) {
  Scenario s = Noiseless();
  s.effects.temperature = TemperatureRamp{20.0, 30.0};
  s.effects.bias_temp_coeff_counts_per_c = {0.5, -0.3, 0.8};
  s.effects.scale_temp_coeff_per_c = {1e-3, 0.0, -2e-3};
  VirtualBench bench(s);
  const std::vector<Capture> captures = bench.SimulateCaptureSet();
  EXPECT_DOUBLE_EQ(captures.front().samples.front().temp_c, 20.0);
  EXPECT_NEAR(captures.back().samples.back().temp_c, 30.0, 0.01);
  // raw = K (1 + s dT) a^a + b + c dT, with dT from the bench temperature (25 degC).
  const double t_s = s.SessionDurationS();  // end of the ramp: dT = +5
  const Eigen::Vector3d f(1.0, -2.0, 9.0);
  const SensorModel& m = s.sensor.model;
  const Eigen::Vector3d a_a = m.Misalignment().inverse() * f;
  const Eigen::Vector3d expected =
      m.scale_counts_per_mps2
          .cwiseProduct(Eigen::Vector3d::Ones() + 5.0 * s.effects.scale_temp_coeff_per_c)
          .cwiseProduct(a_a) +
      m.bias_counts + 5.0 * s.effects.bias_temp_coeff_counts_per_c;
  EXPECT_LT((bench.IdealRaw(f.replicate<1, 3>(), t_s) - expected).norm(), 1e-9);
  EXPECT_LT((bench.IdealRaw(f.replicate<1, 3>(), 0.5 * t_s) - m.Raw(f)).norm(), 1e-9);  // 25 degC
}

TEST(VirtualBench, ReadingsClipAtTheAdcRange) {
  Scenario s = Noiseless();
  s.sensor.model.bias_counts.z() = 4000.0;  // +g on z would read ~4340 > 4095
  VirtualBench bench(s);
  const std::vector<Capture> c = bench.SimulateCaptureSet();
  for (const Sample& smp : c.at(0).samples) ASSERT_EQ(smp.raw_counts.z(), 4095.0);  // z up
  EXPECT_LT(ComputeStats(c.at(1).samples).max_counts.z(), 4095.0);                  // z down
  for (const Capture& cap : c) {
    const CaptureStats st = ComputeStats(cap.samples);
    EXPECT_GE(st.min_counts.minCoeff(), 0.0);
    EXPECT_LE(st.max_counts.maxCoeff(), 4095.0);
  }
}

TEST(VirtualBench, SignedAdcClipsBothWays) {
  Scenario s = Noiseless();
  s.adc = AdcSpec{8, true};  // -128..127
  s.sensor.model.bias_counts.setZero();
  VirtualBench bench(s);
  const CaptureStats up = ComputeStats(bench.SimulateCaptureSet().at(0).samples);  // z up: +341
  EXPECT_EQ(up.max_counts.z(), 127.0);
  const CaptureStats down = ComputeStats(bench.SimulateCaptureSet().at(1).samples);  // z down
  EXPECT_EQ(down.min_counts.z(), -128.0);
}

bool SameSamples(const std::vector<Capture>& a, const std::vector<Capture>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].samples.size() != b[i].samples.size()) return false;
    for (std::size_t k = 0; k < a[i].samples.size(); ++k) {
      if (a[i].samples[k].raw_counts != b[i].samples[k].raw_counts ||
          a[i].samples[k].t_s != b[i].samples[k].t_s) {
        return false;
      }
    }
  }
  return true;
}

TEST(VirtualBench, SameSeedSameOutput) {
  VirtualBench first(DefaultScenario());
  VirtualBench second(DefaultScenario());
  const std::vector<Capture> a = first.SimulateCaptureSet();
  EXPECT_TRUE(SameSamples(a, second.SimulateCaptureSet()));
  EXPECT_TRUE(SameSamples(a, first.SimulateCaptureSet()));  // a second run restarts the stream
  Scenario other = DefaultScenario();
  other.bench.seed += 1;
  EXPECT_FALSE(SameSamples(a, VirtualBench(other).SimulateCaptureSet()));
}

TEST(VirtualBench, BumpIsAHalfSinePulseInsideItsWindow) {
  Scenario s = Noiseless();
  s.bench.placement_error_deg = 0.0;
  s.captures.resize(1);  // z up
  Scenario bumped = s;
  bumped.effects.bumps = {Bump{0, 2.0, 5.0, 0.2}};
  const Capture quiet = VirtualBench(s).SimulateCaptureSet().at(0);
  const Capture hit = VirtualBench(bumped).SimulateCaptureSet().at(0);
  double peak_mps2 = 0.0;
  for (std::size_t k = 0; k < quiet.samples.size(); ++k) {
    const double t_s = quiet.samples[k].t_s;
    const Eigen::Vector3d d = s.sensor.model.Calibrate(hit.samples[k].raw_counts) -
                              s.sensor.model.Calibrate(quiet.samples[k].raw_counts);
    if (t_s < 2.0 || t_s > 2.2) {
      ASSERT_EQ(d.norm(), 0.0) << "at " << t_s;
    } else {
      peak_mps2 = std::max(peak_mps2, d.norm());
      EXPECT_LT(std::abs(d.z()), 0.05);  // horizontal
    }
  }
  EXPECT_NEAR(peak_mps2, 5.0, 0.1);
}

TEST(VirtualBench, RefusesAnInvalidScenario) {
  Scenario s = DefaultScenario();
  s.sensor.noise_counts.x() = -1.0;
  EXPECT_THROW(VirtualBench{s}, Error);
}

}  // namespace
}  // namespace accelcal::sim

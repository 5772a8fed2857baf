// Issue 17 item 2: a mistyped radius or speed gave a calibration, exit 0, no warning (one run at
// r = 0.07 m where the truth is 0.05: chi2/dof 156279, bias_z 14 counts off; radius and rpm
// swapped, r = 120 m at 0.1 rpm, also accepted). The one pipeline (calibration_pipeline.h) must
// refuse such a run or leave it out with the reason, in the output and the calibration file.
#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/app/calibration_pipeline.h"
#include "accelcal/io/calibration_file.h"
#include "test_support.h"

namespace accelcal::pipeline_disagreement_test {
namespace {

using testing::Contains;

constexpr int kRunAt5cm = 9;  // capture 10: x radial, z up, 0.05 m, 120 rpm

std::vector<Capture> BenchCaptures(std::uint64_t seed = 7) {
  sim::Scenario scenario = sim::DefaultScenario();
  scenario.bench.seed = seed;
  sim::VirtualBench bench(scenario);
  return bench.SimulateCaptureSet();
}

CalibrationOutcome Calibrate(std::vector<Capture> captures) {
  CalibrationRequest request;
  request.captures = std::move(captures);
  request.source_name = "set.csv";
  request.screening.adc_range = AdcRange{0, 4095};
  return CalibrateCaptures(std::move(request));
}

// The base model and the truth's z bias: the fit must not have been dragged.
void ExpectSound(const CalibrationOutcome& o) {
  ASSERT_TRUE(o.usable()) << o.diagnosis.base.message;
  const FitSummary& fit = o.Fit(true);
  EXPECT_LT(fit.Chi2PerDof(), 5.0) << FormatDiagnosis(o.diagnosis);
  EXPECT_NEAR(fit.Model().bias_counts.z(), sim::DefaultScenario().sensor.model.bias_counts.z(), 1.0);
}

TEST(PipelineDisagreement, RadiusTyped7cmFor5cmIsLeftOutWithTheReason) {
  std::vector<Capture> captures = BenchCaptures();
  captures[kRunAt5cm].radius_m = 0.07;
  const CalibrationOutcome o = Calibrate(captures);
  ExpectSound(o);
  const Capture& run = o.captures[kRunAt5cm];
  EXPECT_FALSE(run.used());
  EXPECT_TRUE(Contains(run.rejection_reason, "radius")) << run.rejection_reason;
  EXPECT_TRUE(Contains(run.rejection_reason, "0.07")) << run.rejection_reason;
  // ... and the calibration file says so.
  const Calibration cal = CalibrationFromJsonText(CalibrationToJsonText(o.MakeCalibration(true)), "c");
  EXPECT_FALSE(cal.captures[kRunAt5cm].used);
  EXPECT_EQ(cal.captures[kRunAt5cm].reason, run.rejection_reason);
}

// Without the mounting (the up_axis column is optional) the run's centripetal part cannot be
// checked; the leave-one-out finds it: the others predict it far off and agree without it.
TEST(PipelineDisagreement, WithoutTheMountingLeaveOneOutFindsTheRun) {
  std::vector<Capture> captures = BenchCaptures();
  for (Capture& c : captures) c.up_axis.reset();
  captures[kRunAt5cm].radius_m = 0.07;
  const CalibrationOutcome o = Calibrate(captures);
  ExpectSound(o);
  const Capture& run = o.captures[kRunAt5cm];
  EXPECT_FALSE(run.used());
  EXPECT_TRUE(Contains(run.rejection_reason, "disagrees with the other captures")) << run.rejection_reason;
  EXPECT_TRUE(Contains(run.rejection_reason, "radius (0.07 m)")) << run.rejection_reason;
  bool warned = false;
  for (const std::string& w : o.Fit(true).warnings) warned = warned || Contains(w, "capture 10 was left out");
  EXPECT_TRUE(warned);
}

TEST(PipelineDisagreement, RadiusAndSpeedSwappedAreRefusedAsImplausible) {
  std::vector<Capture> captures = BenchCaptures();
  captures[kRunAt5cm].radius_m = 120.0;
  captures[kRunAt5cm].rpm = 0.05;
  const CalibrationOutcome o = Calibrate(captures);
  ExpectSound(o);
  const std::string& why = o.captures[kRunAt5cm].rejection_reason;
  EXPECT_TRUE(Contains(why, "radius 120 m is not a plausible turntable radius")) << why;
  EXPECT_TRUE(Contains(why, "swapped")) << why;
}

TEST(PipelineDisagreement, ARadiusTypedInMillimetresIsRefusedAsImplausible) {
  std::vector<Capture> captures = BenchCaptures();
  captures[kRunAt5cm].radius_m = 50.0;
  const CalibrationOutcome o = Calibrate(captures);
  ExpectSound(o);
  EXPECT_TRUE(Contains(o.captures[kRunAt5cm].rejection_reason, "in mm")) << o.captures[kRunAt5cm].rejection_reason;
}

// When more runs disagree than can be left out, there is no calibration: the fit is refused,
// naming the captures predicted worst.
TEST(PipelineDisagreement, ManyDisagreeingRunsAreRefusedByName) {
  std::vector<Capture> captures = BenchCaptures();
  for (Capture& c : captures) c.up_axis.reset();
  for (int i : {9, 12, 15}) captures[i].radius_m *= 1.4;
  const CalibrationOutcome o = Calibrate(captures);
  EXPECT_FALSE(o.usable());
  const std::string& why = o.diagnosis.base.message;
  EXPECT_TRUE(Contains(why, "the captures disagree with each other")) << why;
  EXPECT_TRUE(Contains(why, "is not a calibration")) << why;
}

TEST(PipelineDisagreement, CleanSetsLoseNothing) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const CalibrationOutcome o = Calibrate(BenchCaptures(seed));
    ASSERT_TRUE(o.usable());
    for (const Capture& c : o.captures) EXPECT_TRUE(c.used()) << c.id << ": " << c.rejection_reason;
  }
}

}  // namespace
}  // namespace accelcal::pipeline_disagreement_test

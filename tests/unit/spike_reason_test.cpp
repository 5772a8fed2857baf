// Issue 17, item 12: the reason of a retry after a bump names the bump's time and size. A still
// pose with a half-sine pulse of known start, length and peak (the virtual bench's bump, built
// here independently of it) is fed to the capture engine; the reason must name the pulse's
// peak (its time within a sample, its size within the noise).
//
// DISABLED: this reproduces the defect and fails today ("x jumped 104 counts (69.3 sigma) at
// t = 4.05 s" for a 138-count pulse peaking at 4.07 s): the capture fails at the first
// stability check after the bump begins (every check_interval_s = 0.05 s), and the reason is
// fixed then, naming the largest sample seen so far, on the rising edge. The fix (the reason
// following the bump to its peak while retrying, or the spike event spanning the bump) is not
// done; enable this test with it.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "accelcal/acquire/capture_engine/capture_engine.h"
#include "capture_engine_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

const SensorModel kModel = sim::DefaultScenario().sensor.model;

CaptureContext Context() {
  CaptureContext c;
  c.rough_model = kModel;
  c.noise_floor = NoiseFloor::Given({1.5, 1.5, 1.7});
  return c;
}

CaptureRequest StaticRequest() {
  CaptureRequest r;
  r.id = 1;
  r.label = "z up";
  r.expected = {"+z", Eigen::Vector3d::UnitZ()};
  r.duration_s = 5.0;
  r.timeout_s = 60.0;
  return r;
}

TEST(SpikeReason, DISABLED_NamesThePeakOfTheBumpAndItsSize) {
  constexpr double kStartS = 4.023, kLengthS = 0.1, kPeakCounts = 138.0;
  testing::SyntheticStream stream(kModel, 1.5);
  std::vector<Sample> samples = stream.Pose({0, 0, 1}, 8.0);
  for (Sample& s : samples) {
    const double u = (s.t_s - kStartS) / kLengthS;
    if (u > 0.0 && u < 1.0) s.raw_counts.x() += std::round(kPeakCounts * std::sin(M_PI * u));
  }
  const double peak_t_s = 4.07;  // the sample nearest kStartS + kLengthS / 2
  CaptureEngine engine(StaticRequest(), CaptureEngineOptions{}, Context());
  std::string reason;
  for (size_t i = 0; i < samples.size() && reason.empty(); i += 5) {
    engine.Feed(std::vector<Sample>(samples.begin() + static_cast<long>(i),
                                    samples.begin() + static_cast<long>(std::min(samples.size(), i + 5))));
    if (engine.state() == CaptureState::kRetrying) reason = engine.Snapshot().reason;
  }
  ASSERT_FALSE(reason.empty()) << "the bump did not interrupt the capture";
  // Read with sscanf, not <regex>: GCC 12 warns (maybe-uninitialized, an error here) inside
  // std::regex in the sanitizer build.
  const size_t at = reason.find("spike: x jumped ");
  ASSERT_NE(at, std::string::npos) << reason;
  double jump_counts = 0, sigmas = 0, t_s = 0;
  ASSERT_EQ(std::sscanf(reason.c_str() + at, "spike: x jumped %lf counts (%lf sigma) at t = %lf s", &jump_counts,
                        &sigmas, &t_s),
            3)
      << reason;
  EXPECT_NEAR(t_s, peak_t_s, 0.006) << reason;
  EXPECT_NEAR(jump_counts, kPeakCounts, 6.0) << reason;
}

}  // namespace
}  // namespace accelcal

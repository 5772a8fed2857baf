// Benchmarks of the calibration path (figures in bench/README.md):
//  - BM_FitSeedPlan: the fit alone on the seed's 18-capture plan (9 static, 9 turntable).
//  - BM_RecordingWholeProcess: the imu_tk Xsens file from disk to fitted parameters: read,
//    detect the 38 static intervals, screen, fit. The target: 10x faster than imu_tk's
//    ~0.22 s for its accelerometer part, i.e. under 22 ms.
#include <filesystem>
#include <random>

#include <benchmark/benchmark.h>

#include "accelcal/calibration/capture_screening.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/io/recording_reader.h"
#include "accelcal/acquire/static_detector.h"

namespace accelcal {
namespace {

std::vector<FitCapture> SeedPlanMeans() {
  SensorModel truth;
  truth.bias_counts = {2051.3, 2037.8, 2069.2};
  truth.scale_counts_per_mps2 = {34.91, 35.42, 34.17};
  truth.a_yz_rad = 0.0042;
  truth.a_zy_rad = -0.0061;
  truth.a_zx_rad = 0.0027;
  const double g = 9.80665, rpm = 120.0, w = rpm * 2 * M_PI / 60;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<FitCapture> out;
  auto add = [&](CaptureKind kind, const Eigen::Vector3d& f, double r) {
    FitCapture c;
    c.id = static_cast<int>(out.size()) + 1;
    c.kind = kind;
    c.radius_m = r;
    c.rpm = kind == CaptureKind::kTurntable ? rpm : kNaN;
    c.n_samples = 1000;
    c.mean_cov_counts2 = Eigen::Matrix3d::Identity() * 0.0025;
    c.mean_counts = truth.Raw(f) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    out.push_back(c);
  };
  for (Eigen::Vector3d up : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 0, 0),
                             Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -1, 0),
                             Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 1, -1), Eigen::Vector3d(1, -1, 1)})
    add(CaptureKind::kStatic, g * up.normalized(), kNaN);
  for (double r : {0.05, 0.10, 0.15}) {
    add(CaptureKind::kTurntable, {-w * w * r, 0, g}, r);
    add(CaptureKind::kTurntable, {0, -w * w * r, g}, r);
    add(CaptureKind::kTurntable, {g, 0, -w * w * r}, r);
  }
  return out;
}

void BM_FitSeedPlan(benchmark::State& state) {
  const std::vector<FitCapture> captures = SeedPlanMeans();
  const FitOptions options;
  for (auto _ : state) {
    FitSummary s = FitCalibration(captures, options);
    if (!s.IsUsable()) state.SkipWithError(s.message.c_str());
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_FitSeedPlan)->Unit(benchmark::kMicrosecond);

void BM_RecordingWholeProcess(benchmark::State& state) {
  const std::string path = std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/imu_tk/xsens_acc.mat";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("imu_tk data not found");
    return;
  }
  FitOptions options;
  options.gravity = GravitySpec::Given(9.81744);
  for (auto _ : state) {
    const std::vector<Sample> samples = ReadRecordingFile(path);
    const StaticDetection detection = DetectStaticIntervals(samples, StaticDetectorOptions{});
    std::vector<Capture> captures = CapturesFromIntervals(samples, detection);
    ScreenCaptures(captures, ScreeningOptions{});
    FitSummary s = FitCalibration(captures, options);
    if (!s.IsUsable()) state.SkipWithError(s.message.c_str());
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_RecordingWholeProcess)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace accelcal

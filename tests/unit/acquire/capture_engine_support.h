// Streams for the capture-engine tests: the virtual bench's captures as a live stream, and
// synthetic still or shaking samples through the default sensor.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"

namespace accelcal::testing {

// A scenario of one static pose held `duration_s`, on the default sensor.
inline sim::Scenario OnePose(const Eigen::Vector3d& up, double duration_s, std::uint64_t seed = 3) {
  sim::Scenario s = sim::DefaultScenario();
  s.bench.seed = seed;
  sim::CapturePlan plan;
  plan.kind = CaptureKind::kStatic;
  plan.label = "pose";
  plan.up = up.normalized();
  plan.duration_s = duration_s;
  s.captures = {plan};
  return s;
}

// The samples of the scenario's first capture.
inline std::vector<Sample> FirstCaptureSamples(const sim::Scenario& scenario) {
  sim::VirtualBench bench(scenario);
  return bench.SimulateCaptureSet().front().samples;
}

// Synthetic samples at 100 Hz through `model`: a still pose, and optionally a hand on the
// table (a 3 Hz sway of `sway_counts` amplitude on x).
class SyntheticStream {
 public:
  SyntheticStream(const SensorModel& model, double noise_counts, std::uint64_t seed = 11)
      : model_(model), noise_(0.0, noise_counts), rng_(seed) {}

  std::vector<Sample> Pose(const Eigen::Vector3d& up, double duration_s, double sway_counts = 0) {
    std::vector<Sample> out;
    const Eigen::Vector3d ideal = model_.Raw(9.80665 * up.normalized());
    const long n = std::lround(duration_s * kRateHz);
    for (long k = 0; k < n; ++k, ++tick_) {
      Sample s;
      s.t_s = static_cast<double>(tick_) / kRateHz;
      s.raw_counts = ideal + Eigen::Vector3d(noise_(rng_), noise_(rng_), noise_(rng_));
      s.raw_counts.x() += sway_counts * std::sin(2.0 * M_PI * 3.0 * s.t_s);
      s.raw_counts = s.raw_counts.array().round();
      out.push_back(s);
    }
    return out;
  }

  static constexpr double kRateHz = 100.0;

 private:
  SensorModel model_;
  std::normal_distribution<double> noise_;
  std::mt19937_64 rng_;
  long tick_ = 0;
};

}  // namespace accelcal::testing

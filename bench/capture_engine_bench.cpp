// The capture engine on a 10 kHz stream: text lines through the sample-line parser, the running
// statistics and the stability checks. The target: a 10 kHz stream with under 5 % of one
// core. `core_pct_at_10kHz` is the CPU time per second of such a stream, in % of one core.
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "accelcal/acquire/capture_engine/capture_engine.h"
#include "accelcal/base/sample_line_parser.h"
#include "accelcal/acquire/sim/scenario.h"

namespace {

using namespace accelcal;

constexpr double kRateHz = 10000.0;
constexpr long kStreamSamples = 200000;  // 20 s of stream

const SensorModel& Model() {
  static const SensorModel model = sim::DefaultScenario().sensor.model;
  return model;
}

// A still sensor, z up, 1.5 counts of noise, rounded to counts.
const std::vector<Sample>& StillSamples() {
  static const std::vector<Sample> samples = [] {
    std::vector<Sample> out;
    std::mt19937_64 rng(1);
    std::normal_distribution<double> noise(0.0, 1.5);
    const Eigen::Vector3d ideal = Model().Raw({0.0, 0.0, 9.80665});
    for (long k = 0; k < kStreamSamples; ++k) {
      Sample s;
      s.t_s = static_cast<double>(k) / kRateHz;
      s.raw_counts = (ideal + Eigen::Vector3d(noise(rng), noise(rng), noise(rng))).array().round();
      out.push_back(s);
    }
    return out;
  }();
  return samples;
}

const std::vector<std::string>& StillLines() {
  static const std::vector<std::string> lines = [] {
    std::vector<std::string> out;
    for (const Sample& s : StillSamples()) {
      out.push_back(fmt::format("{:.4f} {} {} {}", s.t_s, s.raw_counts.x(), s.raw_counts.y(),
                                s.raw_counts.z()));
    }
    return out;
  }();
  return lines;
}

CaptureEngine MakeEngine() {
  CaptureRequest request;
  request.id = 1;
  request.label = "z up";
  request.duration_s = 10.0;
  request.timeout_s = 60.0;
  CaptureContext context;
  context.rough_model = Model();
  context.noise_floor = NoiseFloor::Given({1.5, 1.5, 1.7});
  return CaptureEngine(request, CaptureEngineOptions{}, context);
}

void SetCounters(benchmark::State& state) {
  const double per_iteration = static_cast<double>(kStreamSamples);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kStreamSamples);
  // CPU time for kStreamSamples / kRateHz seconds of stream, as % of one core: elapsed / (n / 1e6).
  state.counters["core_pct_at_10kHz"] = benchmark::Counter(
      per_iteration / (kRateHz * 100.0),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Statistics and stability only: a sliding 2 s static monitor and Welford statistics fed per
// sample, the verdict formed every 0.05 s (as the engine does).
void BM_StabilityMonitor10kHz(benchmark::State& state) {
  const std::vector<Sample>& samples = StillSamples();
  for (auto _ : state) {
    StaticStabilityMonitor monitor(StaticStabilityOptions{}, NoiseFloor::Given({1.5, 1.5, 1.7}),
                                   2.0);
    CaptureStats stats;
    long stable = 0;
    for (long k = 0; k < kStreamSamples; ++k) {
      monitor.Add(samples[static_cast<size_t>(k)]);
      stats.Add(samples[static_cast<size_t>(k)]);
      if (k % 500 == 0) stable += monitor.Verdict().stable ? 1 : 0;
    }
    benchmark::DoNotOptimize(stable);
    benchmark::DoNotOptimize(stats.mean_counts.data());
  }
  SetCounters(state);
}
BENCHMARK(BM_StabilityMonitor10kHz)->Unit(benchmark::kMillisecond);

// The whole path: text lines parsed, then the engine (settle 2 s, capture 10 s, accept).
void BM_ParseAndEngine10kHz(benchmark::State& state) {
  const std::vector<std::string>& lines = StillLines();
  for (auto _ : state) {
    detail::SampleLineParser parser("bench");
    CaptureEngine engine = MakeEngine();
    Sample s;
    long number = 0;
    for (const std::string& line : lines) {
      parser.Parse(line, ++number, &s);  // throws on a malformed line; returns t's offset
      engine.Feed(s);
    }
    if (engine.state() != CaptureState::kAccepted) {
      state.SkipWithError(engine.Snapshot().reason.c_str());
      return;
    }
    benchmark::DoNotOptimize(engine.capture().samples.data());
  }
  SetCounters(state);
}
BENCHMARK(BM_ParseAndEngine10kHz)->Unit(benchmark::kMillisecond);

}  // namespace

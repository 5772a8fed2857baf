// Cost of the virtual bench's long-term bias noise (sim/bias_noise.h) and of the noise
// analysis. The drift procedure streams 12 h at 100 Hz (4.32 M samples) through the sim source,
// so a reading with white noise, bias instability and random walk (scenarios/drift_demo.toml)
// must cost well under a microsecond. Counter: s_per_sample.
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "accelcal/analysis/noise_analysis.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "accelcal/io/scenario_file.h"

namespace {

accelcal::sim::Scenario DriftDemo(bool with_bias_noise) {
  accelcal::sim::Scenario s =
      accelcal::sim::LoadScenario(std::string(ACCELCAL_SOURCE_DIR) + "/scenarios/drift_demo.toml");
  if (!with_bias_noise) s.sensor.bias_noise = accelcal::sim::BiasNoiseSpec{};
  return s;
}

// One hour at 100 Hz, static z up, through VirtualBench::Measure (what SimSource calls).
void BM_SimStaticHour(benchmark::State& state) {
  accelcal::sim::VirtualBench bench(DriftDemo(state.range(0) != 0));
  const accelcal::sim::Mounting mounting = bench.BeginCapture(0, 0.0);
  constexpr long kSamples = 360000;
  for (auto _ : state) {
    bench.Reseed(11);
    for (long k = 0; k < kSamples; ++k) {
      const double t_s = accelcal::sim::SampleTimeS(0.0, k, 100.0);
      benchmark::DoNotOptimize(bench.Measure(bench.SpecificForcePlatform(mounting, t_s), t_s));
    }
  }
  state.counters["s_per_sample"] = benchmark::Counter(
      static_cast<double>(kSamples), benchmark::Counter::kIsIterationInvariantRate |
                                         benchmark::Counter::kInvert);
}
BENCHMARK(BM_SimStaticHour)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The whole analysis of a 1-minute record at 100 Hz (PSD, statistics, normality, spectrum).
void BM_NoiseAnalysisMinute(benchmark::State& state) {
  accelcal::sim::VirtualBench bench(DriftDemo(true));
  const std::vector<accelcal::analysis::NoiseRecord> records = {
      {"bench", "2026-01-01", bench.SimulateCaptureSet()[0].samples}};
  for (auto _ : state) benchmark::DoNotOptimize(accelcal::analysis::AnalyzeNoise(records));
}
BENCHMARK(BM_NoiseAnalysisMinute)->Unit(benchmark::kMicrosecond);

}  // namespace

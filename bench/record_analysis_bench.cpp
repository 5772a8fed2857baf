// The drift analysis of a 12-hour record at 1 kHz (43.2 million samples per axis, three axes):
// Allan deviation, read-offs and 1-minute drift means, streamed through RecordAnalyzer with the
// samples generated on the fly (white noise on a random-walking bias), so the figure is the
// analysis alone. The target: a few seconds on one core, memory not growing with the
// record (the state's size is reported as a counter).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "accelcal/analysis/record_analysis.h"

namespace accelcal {
namespace {

void BM_RecordAnalysis(benchmark::State& state) {
  const double rate_hz = 1000.0;
  const auto samples = static_cast<long>(state.range(0));
  for (auto _ : state) {
    RecordAnalysisOptions options;
    options.rate_hz = rate_hz;
    RecordAnalyzer analyzer(options, "counts");
    std::minstd_rand rng(1);
    // A cheap generator (sum of uniforms) so the figure is dominated by the analysis.
    auto noise = [&rng] {
      return (static_cast<double>(rng()) + static_cast<double>(rng()) - 2147483647.0) * 4.6e-10;
    };
    Eigen::Vector3d bias(2048, 2048, 2048);
    for (long i = 0; i < samples; ++i) {
      for (int a = 0; a < 3; ++a) bias[a] += 3e-4 * noise();
      analyzer.Add(static_cast<double>(i) / rate_hz,
                   bias + Eigen::Vector3d(noise(), noise(), noise()), 25.0);
    }
    const RecordAnalysis r = analyzer.Result();
    benchmark::DoNotOptimize(r.axes[0].curve.points.size());
  }
  state.SetItemsProcessed(state.iterations() * samples);
  state.counters["samples_per_axis"] = static_cast<double>(samples);
}
// 1 minute, 1 hour and 12 hours at 1 kHz.
BENCHMARK(BM_RecordAnalysis)->Arg(60'000)->Arg(3'600'000)->Arg(43'200'000)
    ->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace accelcal

// Cost of the line-stream core of the byte-stream sources: splitting reads into lines, parsing
// them (detail::SampleLineParser) and the status bookkeeping (rate, gaps), as StreamSource does
// per read. Counters: samples_per_s (rate) and s_per_sample. A 10 kHz stream costs
// 10^4 * s_per_sample of one core (e.g. 200 ns per sample => 0.2 %).
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "accelcal/acquire/source/line_stream.h"
#include "accelcal/acquire/source/status_tracker.h"

namespace {

// 5-field lines as a board would send them at 10 kHz.
std::string Lines(long count) {
  std::string text;
  for (long i = 0; i < count; ++i)
    text += fmt::format("{:.4f} {} {} {} 25.1\n", static_cast<double>(i) / 1e4, 2048 + i % 7,
                        2050 - i % 5, 2391 + i % 3);
  return text;
}

// Feeds the text in reads of `state.range(0)` bytes, as a serial port or socket hands it over.
void BM_LineStreamCore(benchmark::State& state) {
  constexpr long kLines = 100000;
  const std::string text = Lines(kLines);
  const size_t read_bytes = static_cast<size_t>(state.range(0));
  std::vector<accelcal::Sample> samples;
  samples.reserve(kLines);
  for (auto _ : state) {
    accelcal::LineStream stream("bench", 256);
    accelcal::StatusTracker tracker(3.0, 2.0, 0.0);
    accelcal::ReadResult result;
    samples.clear();
    for (size_t at = 0; at < text.size(); at += read_bytes) {
      const size_t before = samples.size();
      accelcal::LineStream::FeedResult fed;
      stream.Feed(std::string_view(text).substr(at, read_bytes), &samples, &fed);
      tracker.OnSamples(samples.data() + before, static_cast<long>(samples.size() - before), 0.0,
                        &result);
    }
    benchmark::DoNotOptimize(samples.data());
    if (tracker.status().samples_total != kLines) state.SkipWithError("lost samples");
  }
  const double n = static_cast<double>(state.iterations()) * kLines;
  state.counters["samples_per_s"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
  // Shown with an SI prefix: "95n" is 95 ns of CPU per sample.
  state.counters["s_per_sample"] =
      benchmark::Counter(n, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(text.size()));
}
BENCHMARK(BM_LineStreamCore)->Arg(64)->Arg(4096)->Unit(benchmark::kMillisecond);

}  // namespace

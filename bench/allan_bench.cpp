// The Allan deviation accumulator on a 12-hour record at 1 kHz (43.2 million readings of one
// axis), generated on the fly (never stored): the issue's target is "a few seconds on one core,
// memory that does not grow with the record". For scale: the public allan_variance_ros took
// 727 s for 4.7 million samples (its issue #39).
#include <cmath>
#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>

#include "accelcal/analysis/allan_deviation.h"

namespace {

using namespace accelcal;

constexpr int64_t kSamples = 43'200'000;  // 12 h at 1 kHz
constexpr size_t kBlock = 4096;           // readings handed over per Add call

// White noise (0.02 m/s^2) plus a random walk (1e-5 m/s^2 per step) on gravity, from a
// xorshift generator and an Irwin-Hall sum of four uniforms: cheap, so the benchmark measures
// the accumulator rather than the generator (BM_SyntheticOnly measures the generator alone).
class Synthetic {
 public:
  void Fill(std::vector<double>* out) {
    for (double& v : *out) {
      walk_ += 1e-5 * Normal();
      v = 9.80665 + 0.02 * Normal() + walk_;
    }
  }

 private:
  double Uniform() {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 7;
    state_ ^= state_ << 17;
    return static_cast<double>(state_ >> 11) * 0x1.0p-53;
  }
  double Normal() { return (Uniform() + Uniform() + Uniform() + Uniform() - 2.0) * std::sqrt(3.0); }
  uint64_t state_ = 0x9E3779B97F4A7C15ull;
  double walk_ = 0.0;
};

void BM_SyntheticOnly(benchmark::State& state) {
  std::vector<double> block(kBlock);
  for (auto _ : state) {
    Synthetic gen;
    double sink = 0;
    for (int64_t done = 0; done < kSamples; done += kBlock) {
      gen.Fill(&block);
      sink += block[0];
    }
    benchmark::DoNotOptimize(sink);
  }
  state.counters["samples"] = static_cast<double>(kSamples);
}
BENCHMARK(BM_SyntheticOnly)->Unit(benchmark::kSecond)->Iterations(1);

// One axis: generation + accumulation of 43.2 M readings, then one Curve().
void BM_Allan12h1kHzOneAxis(benchmark::State& state) {
  std::vector<double> block(kBlock);
  size_t state_bytes = 0;
  size_t points = 0;
  for (auto _ : state) {
    AllanOptions options;
    options.tau0_s = 0.001;
    AllanAccumulator acc(options);
    Synthetic gen;
    for (int64_t done = 0; done < kSamples; done += kBlock) {
      gen.Fill(&block);
      acc.Add(block);
    }
    const AllanCurve curve = acc.Curve();
    points = curve.points.size();
    state_bytes = acc.StateBytes();
    benchmark::DoNotOptimize(curve);
  }
  state.counters["samples"] = static_cast<double>(kSamples);
  state.counters["state_MiB"] = static_cast<double>(state_bytes) / (1 << 20);
  state.counters["points"] = static_cast<double>(points);
  state.counters["ns_per_sample"] =
      benchmark::Counter(static_cast<double>(kSamples) * 1e-9,
                         benchmark::Counter::kIsIterationInvariantRate |
                             benchmark::Counter::kInvert);
}
BENCHMARK(BM_Allan12h1kHzOneAxis)->Unit(benchmark::kSecond)->Iterations(1);

// The live curve: Curve() on an accumulator holding 12 h, right after a chunk of new readings
// (the worst case: the pending terms of up to one chunk are summed first).
void BM_AllanCurveOn12hRecord(benchmark::State& state) {
  AllanOptions options;
  options.tau0_s = 0.001;
  AllanAccumulator acc(options);
  Synthetic gen;
  std::vector<double> block(kBlock);
  for (int64_t done = 0; done < kSamples; done += kBlock) {
    gen.Fill(&block);
    acc.Add(block);
  }
  for (auto _ : state) {
    gen.Fill(&block);  // one second of new readings per curve, as the wizard would
    acc.Add(std::span<const double>(block.data(), 1000));
    benchmark::DoNotOptimize(acc.Curve());
  }
}
BENCHMARK(BM_AllanCurveOn12hRecord)->Unit(benchmark::kMillisecond);

}  // namespace

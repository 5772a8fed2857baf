// Reading a bag's IMU topic (bags/bag_sample_stream.h through io/recording_stream.h, as fit,
// allan, noise and apply read it) against reading the same samples as text (the sample reader),
// on the files of the folder named by ACCELCAL_BENCH_BAGS: imu.txt and the bags that
// bench/make_bench_bags.sh writes there (skipped when unset). Reports bytes_per_second (of the
// file) and items_per_second (samples); the goal (issue 34): a bag read at least as fast as
// the text reader reads the same samples as text. Every sample is kept, as fit --recording
// keeps them; the bags stream chunk by chunk (their resident memory in bench/README.md).
#include <cstdlib>
#include <string>
#include <vector>

#include <sys/stat.h>

#include <benchmark/benchmark.h>

#include "accelcal/io/recording_stream.h"

namespace {

// Bytes of a file, or of the files of a folder (a ROS 2 bag folder).
int64_t BytesOf(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return -1;
  if (!S_ISDIR(info.st_mode)) return info.st_size;
  int64_t total = 0;
  for (const char* name : {"/metadata.yaml", "/imu_sqlite_0.db3", "/imu_mcapdir_0.mcap"})
    if (::stat((path + name).c_str(), &info) == 0) total += info.st_size;
  return total;
}

void ReadAll(benchmark::State& state, const std::string& name, bool text) {
  const char* dir = std::getenv("ACCELCAL_BENCH_BAGS");
  const std::string path = dir == nullptr ? "" : std::string(dir) + "/" + name;
  const int64_t bytes = dir == nullptr ? -1 : BytesOf(path);
  if (bytes < 0) {
    state.SkipWithError("set ACCELCAL_BENCH_BAGS to the folder bench/make_bench_bags.sh writes");
    return;
  }
  accelcal::SampleFormat format;
  if (text) {
    format.unit = {accelcal::ReadingUnit::Kind::kMps2, accelcal::ReadingUnit::kDefaultCountsPerUnit};
    format.unit_declared = true;
  }
  int64_t samples = 0;
  for (auto _ : state) {
    try {
      accelcal::RecordingStream stream(path, accelcal::RecordingStream::kDefaultBlockBytes, format);
      std::vector<accelcal::Sample> all;
      if (stream.expected_samples() > 0) all.reserve(static_cast<size_t>(stream.expected_samples()));
      while (stream.AppendNext(&all)) {
      }
      samples += static_cast<int64_t>(all.size());
      benchmark::DoNotOptimize(all.data());
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * bytes);
  state.SetItemsProcessed(samples);
}

void BM_ReadImuText(benchmark::State& state) { ReadAll(state, "imu.txt", true); }
BENCHMARK(BM_ReadImuText)->Unit(benchmark::kMillisecond)->Iterations(3);

#define ACCELCAL_BAG_BENCH(NAME, FILE)                                   \
  void NAME(benchmark::State& state) { ReadAll(state, FILE, false); }    \
  BENCHMARK(NAME)->Unit(benchmark::kMillisecond)->Iterations(3)

ACCELCAL_BAG_BENCH(BM_ReadBagMcapNone, "imu_none.mcap");
ACCELCAL_BAG_BENCH(BM_ReadBagMcapZstd, "imu_zstd.mcap");
ACCELCAL_BAG_BENCH(BM_ReadBagMcapLz4, "imu_lz4.mcap");
ACCELCAL_BAG_BENCH(BM_ReadBagRos1None, "imu_none.bag");
ACCELCAL_BAG_BENCH(BM_ReadBagRos1Lz4, "imu_lz4.bag");
ACCELCAL_BAG_BENCH(BM_ReadBagRos1Bz2, "imu_bz2.bag");
ACCELCAL_BAG_BENCH(BM_ReadBagDb3, "imu.db3");

}  // namespace

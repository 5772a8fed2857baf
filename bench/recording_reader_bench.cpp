// Parse speed of the recording reader on the imu_tk Xsens file (3.3 MB, 51175 lines), and on a
// large recording named by ACCELCAL_BENCH_RECORDING (e.g. the 1-hour 1 kHz still record that
// scripts/bench_peers.sh generates, 96 MB; skipped when unset). Reports bytes_per_second (MB/s);
// the targets: >= 200 MB/s on one core (issue 3), >= 500 MB/s on a large recording (issue 18).
#include <cstdlib>
#include <string>

#include <sys/stat.h>

#include <benchmark/benchmark.h>

#include "accelcal/io/detail/read_file.h"
#include "accelcal/io/recording_reader.h"

namespace {

const std::string kImuTkPath = std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/imu_tk/xsens_acc.mat";

// Parsing only: the text is already in memory.
void BM_ParseRecordingImuTk(benchmark::State& state) {
  std::string text;
  try {
    text = accelcal::detail::ReadWholeFile(kImuTkPath);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  for (auto _ : state) {
    std::vector<accelcal::Sample> samples = accelcal::ParseRecording(text, kImuTkPath);
    benchmark::DoNotOptimize(samples.data());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(text.size()));
}
BENCHMARK(BM_ParseRecordingImuTk)->Unit(benchmark::kMillisecond);

// Reading the file (page cache warm) and parsing it.
void BM_ReadRecordingFileImuTk(benchmark::State& state) {
  int64_t bytes = 0;
  for (auto _ : state) {
    try {
      std::vector<accelcal::Sample> samples = accelcal::ReadRecordingFile(kImuTkPath);
      benchmark::DoNotOptimize(samples.data());
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    bytes += 3326375;  // the file's size (README.md)
  }
  state.SetBytesProcessed(bytes);
}
BENCHMARK(BM_ReadRecordingFileImuTk)->Unit(benchmark::kMillisecond);

// The whole reader (ReadRecording: read, parse, check t, store every sample) on a large file.
void BM_ReadRecordingLarge(benchmark::State& state) {
  const char* path = std::getenv("ACCELCAL_BENCH_RECORDING");
  struct stat info {};
  if (path == nullptr || ::stat(path, &info) != 0) {
    state.SkipWithError("set ACCELCAL_BENCH_RECORDING to a large recording");
    return;
  }
  for (auto _ : state) {
    try {
      accelcal::Recording r = accelcal::ReadRecording(path);
      benchmark::DoNotOptimize(r.samples.data());
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * info.st_size);
}
BENCHMARK(BM_ReadRecordingLarge)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

// Parse speed of the recording reader on the imu_tk Xsens file (3.3 MB, 51175 lines).
// Reports bytes_per_second (MB/s); the target is >= 200 MB/s on one core in a Release build.
#include <string>

#include <benchmark/benchmark.h>

#include "accelcal/io/detail/read_file.h"
#include "accelcal/io/recording_reader.h"

namespace {

const std::string kImuTkPath = std::string(ACCELCAL_SHARED_DATA_DIR) + "/imu_tk/xsens_acc.mat";

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

}  // namespace

#include "accelcal/analysis/analyze_recording.h"

#include <memory>
#include <vector>

#include "accelcal/apply.h"
#include "accelcal/io/recording_stream.h"

namespace accelcal {

RecordAnalysis AnalyzeRecordingFile(const std::string& path, const RecordAnalysisOptions& options,
                                    const std::optional<Calibration>& calibration,
                                    const std::function<void(long samples)>& progress) {
  std::unique_ptr<CalibrationApplier> applier;
  if (calibration) applier = std::make_unique<CalibrationApplier>(*calibration);
  RecordAnalyzer analyzer(options, applier ? "m/s^2" : "counts");
  RecordingStream stream(path);
  std::vector<Sample> block;
  long read = 0;
  while (stream.Next(&block)) {
    for (const Sample& s : block)
      analyzer.Add(s.t_s, applier ? applier->Apply(s) : s.raw_counts, s.temp_c);
    read += static_cast<long>(block.size());
    if (progress) progress(read);
  }
  return analyzer.Result();
}

}  // namespace accelcal

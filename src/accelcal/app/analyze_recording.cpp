#include "accelcal/app/analyze_recording.h"

#include <cmath>
#include <memory>
#include <vector>

#include <fmt/core.h>

#include "accelcal/calibration/apply.h"
#include "accelcal/base/error.h"
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

namespace accelcal {

RecordAnalysis AnalyzeJournalRecord(const SessionJournal& journal, const std::string& step_id,
                                    const RecordAnalysisOptions& options,
                                    const std::optional<Calibration>& calibration) {
  if (journal.RecordSummaryOf(step_id).num_samples == 0)
    throw Error(fmt::format("the session has no record at step '{}'", step_id));
  std::unique_ptr<CalibrationApplier> applier;
  if (calibration) applier = std::make_unique<CalibrationApplier>(*calibration);
  RecordAnalyzer analyzer(options, applier ? "m/s^2" : "counts");
  journal.VisitRecordChunks(step_id, [&](const RecordChunk& chunk) {
    for (const Sample& s : chunk.samples)
      analyzer.Add(s.t_s, applier ? applier->Apply(s) : s.raw_counts,
                   std::isfinite(s.temp_c) ? s.temp_c : kNaN);
  });
  return analyzer.Result();
}

}  // namespace accelcal

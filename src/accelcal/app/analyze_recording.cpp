#include "accelcal/app/analyze_recording.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "accelcal/app/calibration_input.h"
#include "accelcal/bags/bag_open.h"
#include "accelcal/calibration/apply.h"
#include "accelcal/base/error.h"
#include "accelcal/io/recording_stream.h"
#include "accelcal/session/session_store.h"

namespace accelcal {

RecordAnalysis AnalyzeRecordingFile(const std::string& path, const RecordAnalysisOptions& options,
                                    const std::optional<Calibration>& calibration,
                                    const std::function<void(long samples)>& progress,
                                    const SampleFormat& format, ReadingSummary* summary) {
  std::unique_ptr<CalibrationApplier> applier;
  SampleFormat read_as = format;
  if (calibration) {
    if (format.unit_declared && format.unit.Describe() != calibration->reading_unit.Describe())
      throw Error(fmt::format("--unit {}: the calibration was made from readings in {}",
                              format.unit.Describe(), calibration->reading_unit.Describe()));
    read_as.unit = calibration->reading_unit;
    read_as.unit_declared = true;
    applier = std::make_unique<CalibrationApplier>(*calibration);
  }
  RecordingStream stream(path, RecordingStream::kDefaultBlockBytes, read_as);
  // Without a calibration: counts as they are, or a logger's converted readings (a bag's m/s^2)
  // back in m/s^2.
  const ReadingUnit& unit = stream.unit();
  const bool converted = !applier && !unit.is_counts();
  const double to_mps2 = converted ? (unit.kind == ReadingUnit::Kind::kG ? 9.80665 : 1.0) /
                                         unit.counts_per_unit
                                   : 1.0;
  RecordAnalyzer analyzer(options, applier || converted ? "m/s^2" : "counts");
  std::vector<Sample> block;
  long read = 0;
  while (stream.Next(&block)) {
    for (const Sample& s : block)
      analyzer.Add(s.t_s, applier ? applier->Apply(s) : Eigen::Vector3d(s.raw_counts * to_mps2), s.temp_c);
    read += static_cast<long>(block.size());
    if (progress) progress(read);
  }
  if (summary != nullptr) *summary = stream.Summary();
  return analyzer.Result();
}

}  // namespace accelcal

namespace accelcal {
namespace {

// Damaged last chunks (session_journal.h): the record's samples end before them, and the hole is
// listed as a gap like those between samples: the readings it would have held at the record's
// rate (from the last good sample to the damaged part's stated end) are missing. No Allan term
// spans it (nothing comes after it).
void AddEndGap(const RecordGap& gap, RecordAnalysis* r) {
  RecordAnalysisGap g;
  g.t_before_s = gap.t_start_s;
  g.t_after_s = gap.t_end_s;
  if (std::isfinite(r->rate_hz) && r->rate_hz > 0.0)
    g.missing_samples = std::llround(std::max(0.0, gap.duration_s()) * r->rate_hz);
  r->gaps.push_back(g);
  r->missing_samples += g.missing_samples;
}

}  // namespace

RecordAnalysis AnalyzeJournalRecord(const SessionJournal& journal, const std::string& step_id,
                                    const RecordAnalysisOptions& options,
                                    const std::optional<Calibration>& calibration) {
  if (journal.RecordSummaryOf(step_id).num_samples == 0)
    throw Error(fmt::format("the session has no record at step '{}'", step_id));
  std::unique_ptr<CalibrationApplier> applier;
  if (calibration) applier = std::make_unique<CalibrationApplier>(*calibration);
  RecordAnalyzer analyzer(options, applier ? "m/s^2" : "counts");
  std::optional<RecordGap> end_gap;
  long samples_read = 0;
  journal.VisitRecordChunks(step_id, [&](const RecordChunk& chunk) {
    samples_read += static_cast<long>(chunk.samples.size());
    for (const Sample& s : chunk.samples)
      analyzer.Add(s.t_s, applier ? applier->Apply(s) : s.raw_counts,
                   std::isfinite(s.temp_c) ? s.temp_c : kNaN);
    if (chunk.gap_after) end_gap = chunk.gap_after;
  });
  CheckRecordReadable(journal, step_id, samples_read);
  RecordAnalysis result = analyzer.Result();
  if (end_gap) AddEndGap(*end_gap, &result);
  return result;
}

namespace {

// The record step `step_id` (empty: the first) of the session file at `path`, opened read-only;
// *source gets "PATH:STEP".
RecordAnalysis AnalyzeSessionRecordFile(const std::string& path, const std::string& step_id,
                                        const RecordAnalysisOptions& options,
                                        const std::optional<Calibration>& calibration,
                                        std::string* source) {
  SessionOpenOptions read_only;
  read_only.read_only = true;
  const std::unique_ptr<SessionStore> store = SessionStore::Open(path, read_only);
  const std::vector<std::string> steps = store->RecordSteps();
  if (steps.empty())
    throw Error(fmt::format("session {} holds no record (run the drift or noise procedure)", path));
  const std::string step = step_id.empty() ? steps.front() : step_id;
  if (std::find(steps.begin(), steps.end(), step) == steps.end())
    throw Error(fmt::format("session {} has no record at step '{}'; its records: {}", path, step,
                            fmt::join(steps, ", ")));
  *source = path + ":" + step;
  return AnalyzeJournalRecord(*store, step, options, calibration);
}

}  // namespace

RecordInputAnalysis AnalyzeRecordInput(const std::string& path, const std::string& step_id,
                                       const RecordAnalysisOptions& options,
                                       const std::optional<Calibration>& calibration,
                                       const SampleFormat& format) {
  RecordInputAnalysis result;
  result.source = path;
  // A ROS 2 bag (.db3) is an SQLite file too: a recording, as the reader takes it.
  if (path != "-" && IsSessionFile(path) && !bags::DetectBag(path)) {
    result.analysis = AnalyzeSessionRecordFile(path, step_id, options, calibration, &result.source);
    return result;
  }
  result.reading.emplace();
  result.analysis = AnalyzeRecordingFile(path, options, calibration, {}, format, &*result.reading);
  return result;
}

}  // namespace accelcal

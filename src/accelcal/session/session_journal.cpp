// The journal's record helpers shared by every implementation (session_journal.h).
#include "accelcal/session/session_journal.h"

#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/base/duration_text.h"
#include "accelcal/base/safe_text.h"

namespace accelcal {

std::string DamagedCapture::Describe() const {
  const std::string whose = sensor > 0 ? fmt::format(" of sensor {}", sensor + 1) : "";
  return fmt::format("the capture of step '{}'{} (\"{}\") is damaged in the session file ({}): "
                     "left out",
                     ShortDisplayText(step_id, 80), whose, ShortDisplayText(label, 80), problem);
}

void SessionJournal::RecordSensors(const Fixture& /*sensors*/) {
  throw Error("this session journal holds one sensor");
}

void SessionJournal::RecordSensorCaptures(const std::string& step_id,
                                          const std::vector<SensorCapture>& captures) {
  if (captures.size() == 1 && captures.front().sensor == 0) {
    RecordCapture(step_id, captures.front().capture);
    return;
  }
  throw Error("this session journal holds one sensor");
}

void SessionJournal::RecordSensorRedoCaptures(const std::string& step_id,
                                              const std::vector<SensorCapture>& captures,
                                              const std::string& superseded_step_id) {
  if (captures.size() == 1 && captures.front().sensor == 0) {
    RecordRedoCapture(step_id, captures.front().capture, superseded_step_id);
    return;
  }
  throw Error("this session journal holds one sensor");
}

std::vector<JournalCapture> SessionJournal::SensorCaptures(int sensor) const {
  if (sensor == 0) return Captures();
  return {};
}

void SessionJournal::RecordSensorResult(int sensor, const std::string& calibration_json) {
  if (sensor != 0) throw Error("this session journal holds one sensor");
  RecordResult(calibration_json);
}

std::optional<std::string> SessionJournal::SensorResult(int sensor) const {
  if (sensor == 0) return Result();
  return std::nullopt;
}

Fixture SessionSensors(const SessionJournal& journal) {
  if (std::optional<Fixture> sensors = journal.Sensors()) return *sensors;
  std::string serial;
  const SessionInputs inputs = journal.Inputs();
  for (const auto& [step, values] : inputs) {
    if (auto device = values.find(welcome_key::kDevice); device != values.end()) serial = device->second;
  }
  return SingleSensorFixture(serial);
}

void CheckRecordChunk(const std::string& step_id, const RecordChunk& chunk,
                      const RecordSummary& so_far) {
  if (chunk.index != so_far.num_chunks)
    throw Error(fmt::format("record '{}': chunk {} is not the next one ({} stored)", step_id,
                            chunk.index, so_far.num_chunks));
  if (chunk.samples.empty()) throw Error(fmt::format("record '{}': chunk {} is empty", step_id, chunk.index));
  for (size_t i = 0; i < chunk.samples.size(); ++i) {
    const double t = chunk.samples[i].t_s;
    const double before = i == 0 ? so_far.t_last_s : chunk.samples[i - 1].t_s;
    if (!std::isfinite(t) || (!std::isnan(before) && !(t > before)))
      throw Error(fmt::format("record '{}': chunk {} sample {}: t = {} does not come after {}",
                              step_id, chunk.index, i, t, before));
  }
  if (chunk.gap_before) {
    const RecordGap& g = *chunk.gap_before;
    if (so_far.num_chunks == 0 || g.t_start_s != so_far.t_last_s ||
        g.t_end_s != chunk.samples.front().t_s)
      throw Error(fmt::format("record '{}': the gap before chunk {} must span from the last "
                              "sample stored to the chunk's first", step_id, chunk.index));
  }
}

RecordSummary AddToSummary(RecordSummary s, const RecordChunk& chunk) {
  if (s.num_chunks == 0) s.t_first_s = chunk.samples.front().t_s;
  s.t_last_s = chunk.samples.back().t_s;
  s.num_chunks += 1;
  s.num_samples += static_cast<long>(chunk.samples.size());
  s.last_wall_end_s = chunk.wall_end_s;
  if (chunk.gap_before) {
    s.num_gaps += 1;
    s.gaps_s += chunk.gap_before->duration_s();
  }
  return s;
}

JournalRecord ReadRecord(const SessionJournal& journal, const std::string& step_id) {
  JournalRecord out;
  journal.VisitRecordChunks(step_id, [&](const RecordChunk& chunk) {
    if (chunk.gap_before) out.gaps.push_back(*chunk.gap_before);
    out.samples.insert(out.samples.end(), chunk.samples.begin(), chunk.samples.end());
    if (chunk.gap_after) out.gaps.push_back(*chunk.gap_after);
  });
  CheckRecordReadable(journal, step_id, static_cast<long>(out.samples.size()));
  return out;
}

void CheckRecordReadable(const SessionJournal& journal, const std::string& step_id, long samples_read) {
  if (samples_read > 0) return;
  const RecordSummary stored = journal.RecordSummaryOf(step_id);
  if (stored.num_chunks == 0) return;  // nothing was recorded: not damage
  throw Error(fmt::format("record '{}': none of its {} stored chunks can be read: the session file "
                          "is damaged there (their checksums or sizes do not match what was "
                          "written); nothing of this record is used: record it again",
                          step_id, stored.num_chunks));
}

std::string DescribeRecords(const SessionJournal& journal) {
  std::string out;
  for (const std::string& id : journal.RecordSteps()) {
    const RecordSummary r = journal.RecordSummaryOf(id);
    if (!out.empty()) out += "; ";
    out += fmt::format("{}: {} recorded over {}, {} gap{} ({})", id, FormatLongDuration(r.recorded_s()),
                       FormatLongDuration(r.span_s()), r.num_gaps, r.num_gaps == 1 ? "" : "s",
                       FormatLongDuration(r.gaps_s));
  }
  return out;
}

std::vector<JournalCapture> CurrentCaptures(std::vector<JournalCapture> all) {
  std::erase_if(all, [](const JournalCapture& c) { return c.superseded(); });
  return all;
}

}  // namespace accelcal

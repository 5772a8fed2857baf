#include "accelcal/app/noise_records.h"

#include <algorithm>
#include <map>
#include <memory>
#include <set>

#include <sys/stat.h>

#include <fmt/core.h>

#include "accelcal/bags/bag_open.h"
#include "accelcal/base/error.h"
#include "accelcal/io/recording_reader.h"
#include "accelcal/io/recording_stream.h"
#include "accelcal/session/session_catalog.h"

namespace accelcal::analysis {
namespace {

// "A (3 sessions), B (1 session)".
std::string DeviceList(const std::map<std::string, int>& counts) {
  std::string out;
  for (const auto& [device, n] : counts) {
    if (!out.empty()) out += ", ";
    out += fmt::format("{} ({} session{})", device.empty() ? "(no serial)" : device, n,
                       n == 1 ? "" : "s");
  }
  return out;
}

[[noreturn]] void ThrowNoRecords(const std::string& sessions_dir, const std::string& device,
                                 const std::string& title, const NoiseRecordSet& found) {
  const SessionListing noise = ListSessions(sessions_dir, SessionFilter{"", title});
  std::map<std::string, int> devices;
  for (const SessionInfo& info : noise.sessions) ++devices[info.device];
  std::string msg = fmt::format("no noise record of device {} in {} (procedure \"{}\")", device,
                                sessions_dir, title);
  if (!found.notes.empty()) msg += fmt::format("; {}", found.notes.front());
  if (devices.empty()) {
    msg += "; there are no noise sessions there";
  } else {
    msg += "; devices with noise sessions: " + DeviceList(devices);
  }
  throw Error(msg);
}

}  // namespace

NoiseRecordSet NoiseRecordsOfDevice(const std::string& sessions_dir, const std::string& device,
                                    const Procedure& noise_procedure) {
  std::set<std::string> record_steps;
  for (const ProcedureStep& step : noise_procedure.steps)
    if (IsRecordStep(step.kind)) record_steps.insert(step.id);
  if (record_steps.empty())
    throw Error(fmt::format("procedure {} has no `record` step: not a noise procedure",
                            noise_procedure.source_name));
  NoiseRecordSet set;
  const SessionListing listing =
      ListSessions(sessions_dir, SessionFilter{device, noise_procedure.title});
  SessionOpenOptions read_only;
  read_only.read_only = true;
  for (const SessionInfo& info : listing.sessions) {
    const std::unique_ptr<SessionStore> store = SessionStore::Open(info.path, read_only);
    const std::string date = info.created_utc.substr(0, 10);
    // The wizard streams a record step in chunks (record_step_writer.h), read back at every pass
    // of the analysis from the session file, opened again; sessions of schema 1 kept it as one
    // capture (small: held).
    std::string chunked_step;
    for (const std::string& step : store->RecordSteps())
      if (record_steps.count(step) > 0 && chunked_step.empty()) chunked_step = step;
    if (!chunked_step.empty()) {
      const std::string path = info.path;
      NoiseRecordSource source{info.name, date, {}};
      source.replay = [path, chunked_step, read_only, name = info.name](const SamplePieceSink& sink) {
        const std::unique_ptr<SessionStore> again = SessionStore::Open(path, read_only);
        JournalNoiseRecord(*again, chunked_step, name, "").replay(sink);
      };
      set.records.push_back(std::move(source));
      continue;
    }
    const std::vector<JournalCapture> captures = CurrentCaptures(store->Captures());
    const auto it = std::find_if(captures.begin(), captures.end(), [&](const JournalCapture& c) {
      return record_steps.count(c.step_id) > 0;
    });
    if (it == captures.end() || it->capture.samples.empty()) {
      set.notes.push_back(fmt::format("session {} has no record yet: passed over", info.name));
      continue;
    }
    set.records.push_back(HeldRecord(info.name, date, it->capture.samples));
  }
  if (set.records.empty()) ThrowNoRecords(sessions_dir, device, noise_procedure.title, set);
  return set;
}

NoiseRecordSource NoiseRecordFromFile(const std::string& path, const SampleFormat& format,
                                      ReadingSummary* summary) {
  struct stat info {};
  const bool readable_again = path != "-" && (bags::DetectBag(path).has_value() ||
                                              (::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode)));
  if (!readable_again) {
    // Not a regular file: it cannot be read again, so it is held.
    Recording recording = ReadRecording(path, format);
    if (summary != nullptr) *summary = recording.summary;
    return HeldRecord(path, "", std::move(recording.samples));
  }
  auto passes = std::make_shared<int>(0);
  return {path, "", [path, format, summary, passes](const SamplePieceSink& sink) {
            RecordingStream stream(path, RecordingStream::kDefaultBlockBytes, format);
            std::vector<Sample> block;
            while (stream.Next(&block)) sink(block.data(), block.size());
            if (summary != nullptr && (*passes)++ == 0) *summary = stream.Summary();
          }};
}

NoiseRecordSource JournalNoiseRecord(const SessionJournal& journal, const std::string& step_id,
                                     const std::string& label, const std::string& date) {
  return {label, date, [&journal, step_id](const SamplePieceSink& sink) {
            long samples_read = 0;
            journal.VisitRecordChunks(step_id, [&](const RecordChunk& chunk) {
              samples_read += static_cast<long>(chunk.samples.size());
              sink(chunk.samples.data(), chunk.samples.size());
            });
            CheckRecordReadable(journal, step_id, samples_read);
          }};
}

}  // namespace accelcal::analysis

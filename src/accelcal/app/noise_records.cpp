#include "accelcal/app/noise_records.h"

#include <algorithm>
#include <map>
#include <memory>
#include <set>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/io/recording_reader.h"
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
    if (step.kind == StepKind::kRecord) record_steps.insert(step.id);
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
    // The wizard streams a record step in chunks (record_step_writer.h); sessions of schema 1 kept
    // it as one capture.
    std::vector<Sample> samples;
    for (const std::string& step : store->RecordSteps())
      if (record_steps.count(step) > 0 && samples.empty()) samples = ReadRecord(*store, step).samples;
    if (samples.empty()) {
      const std::vector<JournalCapture> captures = CurrentCaptures(store->Captures());
      const auto it = std::find_if(captures.begin(), captures.end(), [&](const JournalCapture& c) {
        return record_steps.count(c.step_id) > 0;
      });
      if (it != captures.end()) samples = it->capture.samples;
    }
    if (samples.empty()) {
      set.notes.push_back(fmt::format("session {} has no record yet: passed over", info.name));
      continue;
    }
    set.records.push_back({info.name, info.created_utc.substr(0, 10), std::move(samples)});
  }
  if (set.records.empty()) ThrowNoRecords(sessions_dir, device, noise_procedure.title, set);
  return set;
}

NoiseRecord NoiseRecordFromFile(const std::string& path, const SampleFormat& format,
                                ReadingSummary* summary) {
  Recording recording = ReadRecording(path, format);
  if (summary != nullptr) *summary = recording.summary;
  return {path, "", std::move(recording.samples)};
}

}  // namespace accelcal::analysis

#include "cli/record_sensors.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>
#include <vector>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/io/capture_set_writer.h"

namespace accelcal::cli {
namespace {

// One sensor's file and writer, made with its first samples (temperature or not).
struct SensorRecording {
  std::string path;
  std::ofstream file;
  std::optional<RecordingWriter> writer;
};

std::string Summary(const SensorSetSource& set) {
  std::vector<std::string> down;
  for (std::size_t i = 0; i < set.sensor_count(); ++i)
    if (set.status(i).link != LinkState::kUp)
      down.push_back(fmt::format("{} {}", set.fixture().sensors[i].serial, LinkStateToString(set.status(i).link)));
  long samples = 0;
  for (std::size_t i = 0; i < set.sensor_count(); ++i) samples += set.status(i).samples_total;
  std::string text = fmt::format("accelcal record: {} sensors, {} up", set.sensor_count(),
                                 set.sensor_count() - down.size());
  for (const std::string& d : down) text += "; " + d;
  return text + fmt::format("; {} samples\n", samples);
}

}  // namespace

std::string SensorRecordingPath(const std::string& output, const std::string& serial) {
  std::string safe;
  for (char c : serial)
    safe += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
  const std::size_t slash = output.find_last_of('/');
  const std::size_t dot = output.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) || dot == slash + 1)
    return output + "." + safe;
  return output.substr(0, dot) + "." + safe + output.substr(dot);
}

void RecordSensorSet(SensorSetSource& set, const std::string& output, double duration_s, bool quiet,
                     volatile const std::sig_atomic_t* interrupted) {
  const std::size_t n = set.sensor_count();
  std::vector<SensorRecording> recordings(n);
  for (std::size_t i = 0; i < n; ++i)
    recordings[i].path = SensorRecordingPath(output, set.fixture().sensors[i].serial);
  double end_s = INFINITY;
  std::string why_stopped = "interrupted";
  SensorSetSamples got;
  using Clock = std::chrono::steady_clock;
  auto next_status = Clock::now() + std::chrono::seconds(1);
  while (!*interrupted) {
    got.Clear();
    set.Read(0.1, &got);
    bool reached = false;
    for (std::size_t i = 0; i < n && i < got.per_sensor.size(); ++i) {
      std::vector<Sample>& samples = got.per_sensor[i];
      if (samples.empty()) continue;
      if (duration_s > 0.0 && std::isinf(end_s)) end_s = samples.front().t_s + duration_s;  // one clock
      while (!samples.empty() && samples.back().t_s >= end_s) {
        samples.pop_back();
        reached = true;
      }
      SensorRecording& r = recordings[i];
      if (!r.writer && !samples.empty()) {
        r.file.open(r.path, std::ios::binary | std::ios::trunc);
        if (!r.file) throw Error("cannot open '" + r.path + "' for writing");
        r.writer.emplace(r.file, std::isfinite(samples.front().temp_c));
      }
      if (r.writer) r.writer->Write(samples);
      if (r.writer && !r.file) throw Error("cannot write '" + r.path + "'");
    }
    if (reached) {
      why_stopped = "duration reached";
      break;
    }
    const bool all_ended = std::all_of(recordings.begin(), recordings.end(), [&](const SensorRecording& r) {
      return set.status(static_cast<std::size_t>(&r - recordings.data())).link == LinkState::kEnded;
    });
    if (all_ended) {
      why_stopped = "end of input";
      break;
    }
    if (Clock::now() >= next_status) {
      for (SensorRecording& r : recordings)
        if (r.writer) r.writer->Flush();  // bounds what an interruption can lose
      if (!quiet) fmt::print(stderr, "{}", Summary(set));
      next_status = Clock::now() + std::chrono::seconds(1);
    }
  }
  for (SensorRecording& r : recordings) {
    if (!r.writer) continue;
    r.writer->Flush();
    r.file.close();
    if (r.file.fail()) throw Error("cannot write '" + r.path + "'");
  }
  if (quiet) return;
  fmt::print(stderr, "{}accelcal record: {}\n", Summary(set), why_stopped);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string& serial = set.fixture().sensors[i].serial;
    if (recordings[i].writer) {
      fmt::print(stderr, "accelcal record: {}: {} samples written to {}\n", serial,
                 recordings[i].writer->written(), recordings[i].path);
    } else {
      const SourceStatus& s = set.status(i);
      fmt::print(stderr, "accelcal record: {}: sent no samples while the others did (its link: {}{}); "
                 "no file written\n", serial, LinkStateToString(s.link),
                 s.link_error.empty() ? "" : ", " + s.link_error);
    }
  }
}

}  // namespace accelcal::cli

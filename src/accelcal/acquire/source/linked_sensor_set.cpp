#include "accelcal/acquire/source/linked_sensor_set.h"

#include <algorithm>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/acquire/source/wall_clock.h"

namespace accelcal {

LinkedSensorSet::LinkedSensorSet(Fixture fixture, std::vector<std::unique_ptr<SampleSource>> sources)
    : fixture_(std::move(fixture)), sources_(std::move(sources)) {
  if (sources_.empty() || sources_.size() != fixture_.sensors.size()) {
    throw Error(fmt::format("{} sources for {} sensors", sources_.size(),
                            fixture_.sensors.size()));
  }
  for (const auto& s : sources_)
    if (!s) throw Error("a sensor without a source");
}

std::string LinkedSensorSet::Describe() const {
  std::string text;
  for (std::size_t i = 0; i < sources_.size(); ++i)
    text += (i ? ", " : "") + fixture_.sensors[i].serial + ": " + sources_[i]->Describe();
  return text;
}

const SourceStatus& LinkedSensorSet::status(std::size_t sensor) const {
  return sources_.at(sensor)->status();
}

ReadResult LinkedSensorSet::Read(double timeout_s, SensorSetSamples* out) {
  out->Resize(sources_.size());
  const double deadline_s = source_detail::WallNowS() + std::max(0.0, timeout_s);
  ReadResult all;
  bool waited = false;
  bool all_ended = true;
  const std::size_t n = sources_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (first_ + k) % n;
    // Only until the first samples: then the rest are read without waiting.
    const double wait_s =
        waited ? 0.0 : std::max(0.0, (deadline_s - source_detail::WallNowS()) / double(n - k));
    const ReadResult one = sources_[i]->Read(wait_s, &out->per_sensor[i]);
    if (one.samples > 0) waited = true;
    MergeReadResult(one, &all);
    all_ended = all_ended && sources_[i]->status().link == LinkState::kEnded;
  }
  first_ = (first_ + 1) % n;
  all.ended = all_ended;
  return all;
}

}  // namespace accelcal

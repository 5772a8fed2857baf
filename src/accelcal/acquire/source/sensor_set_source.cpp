#include "accelcal/acquire/source/sensor_set_source.h"

namespace accelcal {

long SensorSetSamples::total() const {
  long n = 0;
  for (const std::vector<Sample>& samples : per_sensor) n += static_cast<long>(samples.size());
  return n;
}

void SensorSetSamples::Clear() {
  for (std::vector<Sample>& samples : per_sensor) samples.clear();
}

void MergeReadResult(const ReadResult& one, ReadResult* all) {
  all->samples += one.samples;
  all->malformed += one.malformed;
  all->gaps += one.gaps;
  all->link_lost = all->link_lost || one.link_lost;
  all->went_dead = all->went_dead || one.went_dead;
  all->reconnected = all->reconnected || one.reconnected;
  all->notice = all->notice || one.notice;
}

}  // namespace accelcal

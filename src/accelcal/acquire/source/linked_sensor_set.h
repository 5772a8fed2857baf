// Several sensors each on its own link (issue 31): a fixture whose boards each have a serial
// port, an autopilot's IMUs each read as one MAVLink instance (mavlink:...,imu=N), or any mix:
// one SampleSource per sensor, read in turn. The first source with nothing waits up to the
// caller's timeout; once one has delivered, the others are read without waiting, so a silent
// board never holds back the rest.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/acquire/source/sensor_set_source.h"

namespace accelcal {

class LinkedSensorSet final : public SensorSetSource {
 public:
  // sources[i] is fixture's sensor i's; throws accelcal::Error when the counts differ or one is
  // null. The first source's bench (the simulator's), if any, is the set's.
  LinkedSensorSet(Fixture fixture, std::vector<std::unique_ptr<SampleSource>> sources);

  std::string Describe() const override;
  const Fixture& fixture() const override { return fixture_; }
  ReadResult Read(double timeout_s, SensorSetSamples* out) override;
  const SourceStatus& status(std::size_t sensor) const override;
  BenchControl* bench() override { return sources_.front()->bench(); }

 private:
  Fixture fixture_;
  std::vector<std::unique_ptr<SampleSource>> sources_;
  std::size_t first_ = 0;  // whose turn it is to wait: turns rotate so none is always last
};

}  // namespace accelcal

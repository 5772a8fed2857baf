// A live source of several sensors' samples at once (issue 31): the boards of a fixture, the
// IMUs of an autopilot, the 3N columns of one logger's line. Beside SampleSource (one sensor),
// with the same units and rules: t in s on the source's clock (one clock for all the sensors of
// one source), raw in counts, timeouts in s of wall time, one thread at a time, nothing printed.
//
// Sensor i is the fixture's sensor i (fixture().sensors[i]: its serial, its mounting on the
// plate). Each sensor has its own status: a dead board's link is dead while the others are up,
// and a sensor whose samples stop never holds back the others' (a Read returns what arrived).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/fixture.h"
#include "accelcal/acquire/source/source_status.h"

namespace accelcal {

class BenchControl;

// One Read's samples, sensor by sensor: per_sensor[i] are sensor i's, in order, t increasing.
struct SensorSetSamples {
  std::vector<std::vector<Sample>> per_sensor;

  void Resize(std::size_t sensors) { per_sensor.resize(sensors); }
  long total() const;
  void Clear();
};

class SensorSetSource {
 public:
  SensorSetSource() = default;
  SensorSetSource(const SensorSetSource&) = delete;
  SensorSetSource& operator=(const SensorSetSource&) = delete;
  virtual ~SensorSetSource() = default;

  // "sim --sensors 8", "file:plate.txt (3 sensors by --columns)", ...
  virtual std::string Describe() const = 0;
  // The sensors in order (serials, mountings); at least one.
  virtual const Fixture& fixture() const = 0;
  std::size_t sensor_count() const { return fixture().sensors.size(); }

  // Waits at most timeout_s (>= 0) for data and appends each sensor's samples that arrived to
  // out->per_sensor[i] (resized to sensor_count() first). Returns as soon as some samples were
  // appended, or at the timeout, or at once when every sensor has ended. The result merges the
  // sensors' events (samples: all of them; went_dead: some sensor went dead in this call; ended:
  // the last live sensor ended). Never throws for bad data or a failing link.
  virtual ReadResult Read(double timeout_s, SensorSetSamples* out) = 0;

  // Sensor i's status as of the end of the last Read (i < sensor_count()).
  virtual const SourceStatus& status(std::size_t sensor) const = 0;

  // The simulated bench's controls, which move the whole plate; nullptr for real sources.
  virtual BenchControl* bench() { return nullptr; }
};

// Merges one sensor's ReadResult into the call's (counts add up, flags or'ed).
void MergeReadResult(const ReadResult& one, ReadResult* all);

}  // namespace accelcal

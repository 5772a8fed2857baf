// A live source of raw accelerometer samples: the simulated bench, a recording replayed, a serial
// port, a TCP sample server or standard input, all behind one interface (htop's Platform idea:
// one API, several backends, the simulator standing in for hardware). OpenSource
// (source_spec.h) makes one from a spec string such as "serial:/dev/ttyUSB0@115200".
//
// Units: sample t in s on the source's clock (monotonic, the `t` of the line protocol), raw in
// ADC counts, temp_c in degC; timeouts in s of wall time.
//
// Threading: a source is used from one thread at a time. Nothing here prints.
#pragma once

#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/acquire/source/source_status.h"

namespace accelcal {

class BenchControl;

class SampleSource {
 public:
  SampleSource() = default;
  SampleSource(const SampleSource&) = delete;
  SampleSource& operator=(const SampleSource&) = delete;
  virtual ~SampleSource() = default;

  // The spec this source was opened from, normalized: "sim", "file:rec.txt",
  // "serial:/dev/ttyUSB0@115200", "tcp:beagle:5000", "-".
  virtual std::string Describe() const = 0;

  // Waits at most timeout_s (wall clock, >= 0) for data and appends the samples that arrived to
  // *out (in order, t strictly increasing). Returns as soon as some samples were appended, or
  // when the timeout expires, or at once when the source has ended. Never throws for bad data
  // or a failing link: those are reported in the result and in status(). Opening, reconnecting
  // and the dead-link check happen inside Read, so call it regularly.
  virtual ReadResult Read(double timeout_s, std::vector<Sample>* out) = 0;

  // The status as of the end of the last Read.
  virtual const SourceStatus& status() const = 0;

  // What the source's line reading understood so far (columns, rate, repaired time stamps), one
  // line (base/sample_reader.h); empty for a source that reads no lines (the simulator).
  virtual std::string DescribeReading() const { return {}; }

  // The simulated bench's controls (place the sensor); nullptr for every real source, since
  // only the simulator can move the sensor. The pointer is owned by the source.
  virtual BenchControl* bench() { return nullptr; }
};

}  // namespace accelcal

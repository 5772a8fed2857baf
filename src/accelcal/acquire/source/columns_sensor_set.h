// Several sensors on one text line (issue 31): a logger that prints `t ax ay az ax ay az ...`
// over a file, standard input, a serial port or TCP, its 3N columns named by `--columns`
// (base/sensor_columns.h). The link is read once; each line goes to one line reader per sensor
// (LineStream, with that sensor's columns), so a sensor's field that is not a number is that
// sensor's malformed line, and the others' samples of the same line still count.
//
// Link handling is StreamSource's own (link_reader.h: poll() and read() within the caller's
// timeout, a serial or TCP link reopened with back-off after it drops, its partial line
// dropped, a file or standard input finished at its end). Samples are delivered as fast as they
// are read (no pacing by t). Each sensor has its own status; the link's events are every
// sensor's.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "accelcal/acquire/source/byte_link.h"
#include "accelcal/acquire/source/line_stream.h"
#include "accelcal/acquire/source/link_reader.h"
#include "accelcal/acquire/source/sensor_set_source.h"
#include "accelcal/acquire/source/source_options.h"
#include "accelcal/acquire/source/status_tracker.h"

namespace accelcal {

class ColumnsSensorSet final : public SensorSetSource, private LinkEvents {
 public:
  // `columns`: one layout per sensor (SplitSensorColumns), as many as `fixture`'s sensors.
  // Reads options' stream settings (dead_after_s, gap_factor, reconnect_*, max_line_bytes,
  // format but its columns). Throws accelcal::Error when the counts differ.
  ColumnsSensorSet(std::unique_ptr<ByteLink> link, Fixture fixture,
                   const std::vector<std::vector<NamedColumn>>& columns,
                   const SourceOptions& options);
  ~ColumnsSensorSet() override;

  std::string Describe() const override;
  const Fixture& fixture() const override { return fixture_; }
  ReadResult Read(double timeout_s, SensorSetSamples* out) override;
  const SourceStatus& status(std::size_t sensor) const override;

 private:
  struct Lane {
    Lane(const std::string& name, long max_line_bytes, const SampleFormat& format,
         double gap_factor, double dead_after_s, double now_s)
        : lines(name, max_line_bytes, format), tracker(gap_factor, dead_after_s, now_s) {}
    LineStream lines;
    StatusTracker tracker;
    ReadResult result;  // this call's
  };

  void OnLinkOpen() override;
  void OnLinkOpenFailed(const std::string& error) override;
  void OnBytes(std::string_view bytes) override;
  void OnLinkEnd(const std::string& described, bool failed, bool reopens) override;
  // Sensor i's samples appended to out_ since `first`, counted in its status.
  void Counted(std::size_t i, std::size_t first, double now_s);
  void ParseLanes(const std::function<void(Lane&, std::vector<Sample>*, LineStream::FeedResult*)>& parse);

  LinkReader reader_;
  Fixture fixture_;
  std::vector<std::unique_ptr<Lane>> lanes_;
  SensorSetSamples* out_ = nullptr;  // the Read in progress
  SensorSetSamples scratch_;         // samples outside a Read (none: bytes come only in a Read)
};

}  // namespace accelcal

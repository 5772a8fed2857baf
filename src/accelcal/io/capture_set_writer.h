// Writing a capture set as text (the capture-set CSV), and a continuous recording.
//
// Capture-set format (the reader follows it exactly):
//   # accelcal capture set
//   # adc_range_counts = MIN,MAX                    (only when the set carries an ADC range)
//   capture,kind,t,ax,ay,az,temp_c,radius_m,rpm,label,up_axis
//   1,static,0,2051,2040,2403,25,,,z up
//   ...
// Lines starting with '#' are comments. One row per sample; the rows of a capture are
// contiguous. capture: integer id. kind: static | turntable. t: s on the session clock.
// ax, ay, az: raw counts. temp_c: degC, empty when unknown. radius_m (m) and rpm: empty on
// static rows. label: quoted with double quotes when it holds a comma or a quote, quotes
// doubled inside (RFC 4180). up (the requested up direction, "+z" or three numbers) only when
// some capture knows it, as a last column. Numbers are written shortest-round-trip (a whole number of counts
// prints as an integer), so reading them back gives the same doubles.
//
// Recording format: comment lines starting with '#', then one line per sample
// "t ax ay az temp_c" separated by single spaces (temp_c left out when no sample has one).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/capture_set.h"

namespace accelcal {

// Throws accelcal::Error when the stream fails or a label holds a line break.
void WriteCaptureSet(std::ostream& out, const CaptureSet& set);
// Writes to `path` (replacing it). Throws accelcal::Error naming the path on I/O failure.
void WriteCaptureSetFile(const std::string& path, const CaptureSet& set);

// Throws accelcal::Error when the stream fails.
// Writes a continuous recording as it arrives (the same format as WriteRecording), so a long
// record streams to disk with bounded memory. Does NOT take ownership of `out`, which must
// outlive the writer. Throws accelcal::Error when the stream fails.
class RecordingWriter {
 public:
  // Writes the header; `with_temperature` decides whether lines carry temp_c (NaN otherwise).
  RecordingWriter(std::ostream& out, bool with_temperature);
  void Write(const std::vector<Sample>& samples);
  void Flush();
  long written() const { return written_; }

 private:
  std::ostream& out_;
  bool with_temperature_;
  long written_ = 0;
};

void WriteRecording(std::ostream& out, const std::vector<Sample>& samples);

}  // namespace accelcal

// The SampleSource of every byte-stream link (file, standard input, serial port, TCP): reads
// what the link delivers with poll() and read() (never blocking past the caller's timeout),
// splits and parses lines (LineStream), keeps the status (StatusTracker), and reopens a link
// that reopens (serial, TCP) with exponential back-off after it drops. A file can be paced by t.
//
// A dropped link loses its unterminated last line (a fragment, never mis-parsed as a short
// sample); lines already received are kept. t must keep increasing across a reconnect (the
// protocol's monotonic clock): a sender that restarts its clock at 0 gets its lines reported
// as malformed until t passes the last one received.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accelcal/acquire/source/byte_link.h"
#include "accelcal/acquire/source/line_stream.h"
#include "accelcal/acquire/source/link_reader.h"
#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/acquire/source/source_options.h"
#include "accelcal/acquire/source/status_tracker.h"

namespace accelcal {

class StreamSource final : public SampleSource, private LinkEvents {
 public:
  enum class Pacing {
    kAsFastAsPossible,  // deliver samples as soon as they are read
    kByT,               // deliver each sample when the wall clock reaches its t (replay)
  };

  // Takes ownership of `link`; reads only options' stream settings (dead_after_s, gap_factor,
  // reconnect_*, max_line_bytes, format).
  StreamSource(std::unique_ptr<ByteLink> link, const SourceOptions& options, Pacing pacing);
  ~StreamSource() override;

  std::string Describe() const override { return reader_.Describe(); }
  ReadResult Read(double timeout_s, std::vector<Sample>* out) override;
  const SourceStatus& status() const override { return tracker_.status(); }
  std::string DescribeReading() const override;

 private:
  void OnLinkOpen() override;
  void OnLinkOpenFailed(const std::string& error) override;
  void OnBytes(std::string_view bytes) override;
  void OnLinkEnd(const std::string& described, bool failed, bool reopens) override;
  void Deliver(double now_s, std::vector<Sample>* out, ReadResult* result);
  bool Backlogged() const;
  double NextDueWallS() const;
  size_t pending() const { return parsed_.size() - next_; }

  LinkReader reader_;
  Pacing pacing_;
  LineStream lines_;
  StatusTracker tracker_;
  ReadResult* result_ = nullptr;  // the Read in progress, for the link's events
  ReadResult scratch_;            // events outside a Read
  std::vector<Sample> parsed_;  // parsed but not yet delivered, from index next_
  size_t next_ = 0;
  double pace_origin_wall_s_;   // kByT: wall time the first sample was delivered
  double pace_origin_t_s_;      // kByT: its t
  double last_burst_wall_s_ = -1e300;  // kByT: wall time of the last delivery, s
};

}  // namespace accelcal

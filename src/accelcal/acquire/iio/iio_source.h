// iio:DEVICE[,root=DIR][,dev=FILE][,x=CH,y=CH,z=CH][,rate=HZ][,poll]: a Linux IIO accelerometer
// (ADXL345, MPU-6050, LIS3DH, BMI160: in_accel_{x,y,z}) or three channels of an ADC behind an
// analog sensor (x=voltage0,y=voltage1,z=voltage2) as a sample source. root= reads another tree
// than /sys/bus/iio/devices, dev= another file than /dev/iio:deviceN (tests: a tree of files
// and a FIFO).
//
// Buffered (the device has a buffer and the three channels are scan elements): the three
// channels and the timestamp channel are enabled (every other scan element disabled), the
// sampling frequency set when rate= asks and read back, the buffer enabled, and the records read
// from the device file as they come; t is the timestamp channel (ns) from the first record, else
// the record's index over the sampling frequency. A jump of the timestamps beyond 1.5 periods is
// a buffer overrun (or lost records), named with the samples lost. Without a buffer (or with
// `poll`) the *_raw files are read at rate= (else the sampling frequency, else 100 Hz) and t is
// the wall clock: the rate reached is measured and said.
//
// Readings stay counts: the model wants counts, so _scale and _offset are stated
// (DescribeReading), never applied. A read that fails (-EIO) is named with its file; a device that
// disappears (its directory gone, its file ended) drops the link, which is tried again with
// back-off, as a serial port is.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/iio/iio_device.h"
#include "accelcal/acquire/source/reconnect_backoff.h"
#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/acquire/source/source_options.h"
#include "accelcal/acquire/source/status_tracker.h"

namespace accelcal {

class IioSource final : public SampleSource {
 public:
  // Reads options' dead_after_s, gap_factor and reconnect_*. Throws accelcal::Error when the
  // device cannot be found or read (FindIioDevice).
  IioSource(IioSourceSpec spec, const SourceOptions& options);
  ~IioSource() override;

  std::string Describe() const override { return spec_.Describe(); }
  ReadResult Read(double timeout_s, std::vector<Sample>* out) override;
  const SourceStatus& status() const override { return tracker_.status(); }
  std::string DescribeReading() const override;

  const IioDevice& device() const { return device_; }
  bool buffered() const { return buffered_; }

 private:
  bool TryOpen(double deadline_s, ReadResult* result);
  bool StartBuffer(std::string* error);
  void StopBuffer();
  void ReadRecords(ReadResult* result);
  void DecodeRecords(ReadResult* result);
  void PollDue(double now_s, ReadResult* result);
  void Lost(const std::string& why, ReadResult* result);
  std::string Named(const std::string& what) const;

  IioSourceSpec spec_;
  IioDevice device_;
  bool buffered_ = false;
  StatusTracker tracker_;
  ReconnectBackoff backoff_;
  bool open_ = false;
  int fd_ = -1;
  int record_bytes_ = 0;
  std::vector<std::uint8_t> pending_;  // bytes of a record not complete yet
  std::vector<Sample> ready_;
  double rate_hz_ = kNaN;          // the device's (read back) or the poll rate
  std::string rate_note_;          // what was asked and what was read back
  double t0_wall_s_ = 0.0;         // poll: t = wall - t0
  double next_poll_wall_s_ = 0.0;
  std::optional<std::int64_t> first_timestamp_ns_;
  long records_ = 0;
  long overruns_ = 0;
  long lost_samples_ = 0;
  std::string last_read_error_;
  std::string lost_why_;  // why the device was lost, until it is back
  std::string last_loss_;  // the same, until samples come again (says why the link is silent)
};

// Opens the source (FindIioDevice first: a device that is not there is refused at once).
std::unique_ptr<SampleSource> OpenIioSource(const IioSourceSpec& spec, const SourceOptions& options);

}  // namespace accelcal

// Choosing a sample source with a spec string (the `--source` flag):
//
//   sim                         the virtual bench, live (the default)
//   file:PATH                   replay a recording (paced by t with SourceOptions::realtime), or
//                               a ROS bag's IMU topic (bag_source.h)
//   serial:DEVICE@BAUD          a serial port in raw mode, e.g. serial:/dev/ttyUSB0@115200
//   tcp:HOST:PORT               a TCP sample server, e.g. tcp:192.168.7.2:5000, tcp:[::1]:5000
//   -                           standard input
//   mavlink:LINK[,imu=N,...]    a flight controller's IMU over MAVLink (mavlink/mavlink_source.h)
//   iio:DEVICE[,root=DIR,...]   a Linux IIO accelerometer or ADC (iio/iio_source.h)
//
// file, serial, tcp and - carry the line protocol of line_stream.h (docs/formats.md, "Sample sources").
#pragma once

#include <memory>
#include <string>

#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/acquire/source/source_options.h"

namespace accelcal {

enum class SourceKind { kSim, kFile, kSerial, kTcp, kStdin, kMavlink, kIio };

// A spec taken apart; only the fields of its kind are set.
struct SourceSpec {
  SourceKind kind = SourceKind::kSim;
  std::string path;  // file: the recording; serial: the device; mavlink, iio: the whole spec
  long baud = 0;     // serial
  std::string host;  // tcp (without brackets)
  int port = 0;      // tcp, 1..65535
};

// Throws accelcal::Error with what was expected for a malformed spec, e.g. "unknown source
// 'foo': expected sim, file:PATH, serial:DEVICE@BAUD, tcp:HOST:PORT or -".
SourceSpec ParseSourceSpec(const std::string& spec);

// Opens the source `spec` names. Throws accelcal::Error for a bad spec or options, an
// unsupported baud rate, a file that cannot be opened, or a scenario that cannot be loaded.
// Links that can come and go (serial, TCP) are not opened here: a port that is absent or a
// server that refuses shows up in status() and is retried.
std::unique_ptr<SampleSource> OpenSource(const std::string& spec, const SourceOptions& options);

}  // namespace accelcal

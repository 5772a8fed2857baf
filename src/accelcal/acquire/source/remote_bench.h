// The virtual bench behind another process: its controls (bench_control.h) sent over TCP, so
// that a wizard reading a real link (TCP text, a MAVLink vehicle, an IIO device) can still place
// the simulated sensor whose samples travel that link. The test peers use it: `accelcal record
// --source sim --bench-listen 127.0.0.1:0 -o -` streams the bench (and serves its controls),
// a peer turns the stream into MAVLink frames or an IIO device, and `accelcal wizard --source
// mavlink:... --bench-control 127.0.0.1:PORT` places the sensor as it would the in-process sim.
//
// Protocol: one text line each way per command.
//   -> hold                          <- held      the server stops taking samples from the bench
//   -> static UX UY UZ YAW_RAD       <- ok        PlaceStatic, then samples flow again
//   -> turntable R_M RPM RADIAL UP   <- ok        PlaceTurntable ("+x", "-z", ...)
//   -> stop | feet TX TY | level     <- ok        StopTurntable, AdjustTableFeet, LevelTurntable
//   (<- error WHAT when the bench refuses.)
//
// Why "hold" first: samples already on their way (in pipes, in the peer, in the link) were made
// before the placement; the in-process sim has none. After "held" the client reads and drops
// what still arrives until the link has been quiet for kQuietS, and only then places: every
// sample it delivers afterwards was made after the placement, as with the in-process sim. (The
// held bench's clock does not stop: its next samples come at once, already placed.)
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "accelcal/acquire/source/host_port.h"
#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/acquire/source/sensor_set_source.h"

namespace accelcal {

// `source` with the controls of the bench served at `bench`. Connects at the first placement.
std::unique_ptr<SampleSource> WithRemoteBench(std::unique_ptr<SampleSource> source, const HostPort& bench);
// The same for several sensors on links the one bench feeds (a vehicle's IMUs, issue 31): the
// placement moves them all; every sensor's link is drained before it.
std::unique_ptr<SensorSetSource> WithRemoteBench(std::unique_ptr<SensorSetSource> set, const HostPort& bench);

// The serving side, for `accelcal record`: listens, takes one client at a time.
class RemoteBenchServer {
 public:
  // Throws accelcal::Error when it cannot listen. Port 0 picks a free one (port()).
  RemoteBenchServer(const HostPort& listen, BenchControl* bench);
  ~RemoteBenchServer();
  RemoteBenchServer(const RemoteBenchServer&) = delete;
  RemoteBenchServer& operator=(const RemoteBenchServer&) = delete;

  int port() const { return port_; }
  // Serves what has arrived, without waiting unless a client holds the bench: then it waits
  // (calling `flush` first, so that what was taken reaches the peer) for the command that
  // releases it. Returns when samples may be taken again.
  void Serve(const std::function<void()>& flush);

 private:
  bool ReadLine(std::string* line, int timeout_ms);
  void Answer(const std::string& line);
  std::string Execute(const std::string& command);
  void DropClient();

  BenchControl* bench_;
  int listen_fd_ = -1;
  int client_fd_ = -1;
  int port_ = 0;
  std::string inbox_;
};

}  // namespace accelcal

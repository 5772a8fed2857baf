// The four ways to reach a vehicle (the spec after "mavlink:"):
//
//   serial:DEVICE@BAUD   a telemetry radio or the autopilot's USB port, raw 8N1, read and write
//   tcp:HOST:PORT        the vehicle listens and we connect (ArduPilot SITL's 5760, a WiFi bridge)
//   udp:ADDR:PORT        we listen on ADDR:PORT and answer whoever sends to it (a GCS port, 14550)
//   udpout:HOST:PORT     we send to HOST:PORT first and listen for the answers (the vehicle
//                        waits for a ground station to speak: MAVProxy's --out udpin:, SITL's 14555)
//
// A transport moves bytes (a stream) or datagrams (UDP; each holds whole frames) both ways,
// without blocking. Serial and TCP drop and reopen as the text links do (byte_link.h); a UDP
// socket stays open, and a vehicle that goes silent on it is found by its missing heartbeats.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "accelcal/acquire/source/byte_link.h"

namespace accelcal::mavlink {

enum class LinkKind { kSerial, kTcp, kUdp, kUdpOut };

struct LinkSpec {
  LinkKind kind = LinkKind::kTcp;
  std::string path;  // serial: the device
  long baud = 0;     // serial
  std::string host;  // tcp, udpout: where the vehicle is; udp: the address we listen on
  int port = 0;
};

// Throws accelcal::Error naming `whole_spec` for a malformed link, e.g. "source
// 'mavlink:tcp:x': expected mavlink:tcp:HOST:PORT, e.g. mavlink:tcp:127.0.0.1:5760".
LinkSpec ParseLinkSpec(const std::string& link, const std::string& whole_spec);
// "serial:/dev/ttyACM0@115200", "tcp:127.0.0.1:5760", "udp:0.0.0.0:14550", "udpout:10.0.0.2:14555".
std::string DescribeLink(const LinkSpec& spec);

class Transport {
 public:
  using OpenStep = ByteLink::OpenStep;
  virtual ~Transport() = default;
  virtual std::string Describe() const = 0;
  virtual OpenStep Open(double timeout_s, std::string* error) = 0;
  virtual int fd() const = 0;
  virtual void Close() = 0;
  // Bytes read without waiting: > 0, 0 when the other end closed a stream, -1 with errno set
  // (EAGAIN: nothing there).
  virtual ssize_t Receive(std::uint8_t* buffer, size_t size) = 0;
  // Sends one frame (or several concatenated). False with *error when it could not go out (a
  // UDP listener that has heard nobody yet, a full or broken stream).
  virtual bool Send(const std::vector<std::uint8_t>& bytes, std::string* error) = 0;
};

// Throws accelcal::Error for an unsupported baud rate. Nothing is opened here.
std::unique_ptr<Transport> MakeTransport(const LinkSpec& spec);

}  // namespace accelcal::mavlink

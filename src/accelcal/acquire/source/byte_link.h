// How a byte-stream source gets its file descriptor: a file, standard input, a serial port or a
// TCP connection. StreamSource does the reading, line splitting, bookkeeping and retrying; a
// link only opens and closes. Internal to the sources (OpenSource builds them).
#pragma once

#include <string>

namespace accelcal {

class ByteLink {
 public:
  enum class OpenStep {
    kOpen,     // fd() is readable from now on
    kPending,  // still opening (a TCP connect in progress); call Open again
    kFailed,   // did not open; *error says why
  };

  ByteLink() = default;
  ByteLink(const ByteLink&) = delete;
  ByteLink& operator=(const ByteLink&) = delete;
  virtual ~ByteLink() = default;

  // The spec: "file:rec.txt", "serial:/dev/ttyUSB0@115200", "tcp:host:5000", "-".
  virtual std::string Describe() const = 0;
  // Opens, or goes on opening, waiting at most timeout_s. After kFailed the caller waits
  // (back-off) and calls Open again.
  virtual OpenStep Open(double timeout_s, std::string* error) = 0;
  // The open descriptor (valid after kOpen until Close).
  virtual int fd() const = 0;
  // Closes the descriptor if this link owns it. Safe to call when closed.
  virtual void Close() = 0;
  // True when end of data means "the link dropped, open it again" (serial, TCP); false when it
  // means "finished" (a file, standard input).
  virtual bool reopens() const = 0;
};

}  // namespace accelcal

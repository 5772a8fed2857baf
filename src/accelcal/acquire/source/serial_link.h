// serial:DEVICE@BAUD: a serial port (USB adapter, UART) in raw mode (termios cfmakeraw: 8 data
// bits, no parity, no echo, no line editing), at one of the standard baud rates, opened with
// O_NOCTTY so it never becomes the controlling terminal. A cut cable (the device gone, a read
// error, a hang-up) drops the link; StreamSource reopens it with back-off.
#pragma once

#include <memory>
#include <string>

#include "accelcal/acquire/source/byte_link.h"

namespace accelcal {

// True for a baud rate termios supports (300 .. 4000000, the standard list).
bool IsSupportedBaudRate(long baud);
// "300, 1200, ..., 4000000", for messages.
std::string SupportedBaudRatesText();

// The port is opened on the first Open call (a missing device is a failed attempt, retried).
// Throws accelcal::Error for an unsupported baud rate, listing the supported ones. read_write:
// opened for writing too (a MAVLink link sends heartbeats and requests); else read only.
std::unique_ptr<ByteLink> MakeSerialLink(const std::string& device, long baud, bool read_write = false);

}  // namespace accelcal

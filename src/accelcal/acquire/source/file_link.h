// Byte links that end: a recording file (file:PATH) and standard input ("-"). End of data
// means the source is finished (LinkState::kEnded), never a dropped link.
#pragma once

#include <memory>
#include <string>

#include "accelcal/acquire/source/byte_link.h"

namespace accelcal {

// Opens `path` for reading now. Throws accelcal::Error "cannot open 'PATH': <reason>".
std::unique_ptr<ByteLink> OpenFileLink(const std::string& path);

// Reads the descriptor `fd` (0 for standard input; a test may pass a pipe). Does NOT take
// ownership: the descriptor stays open, and must stay open as long as the link is read.
std::unique_ptr<ByteLink> MakeStdinLink(int fd);

}  // namespace accelcal

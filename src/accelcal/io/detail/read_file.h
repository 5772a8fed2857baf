// Reading a whole file into memory (the readers parse from one buffer, which is both simpler
// and faster than line-by-line stream reads).
#pragma once

#include <string>

namespace accelcal::detail {

// The bytes of the file at `path`, unchanged.
// Throws accelcal::Error "cannot open 'PATH': <strerror>" (or "cannot read ...") on failure.
std::string ReadWholeFile(const std::string& path);

}  // namespace accelcal::detail

// Reading and writing whole text files at the edge: a file read in one piece (once: a pipe
// works) and written atomically (atomic_write.h).
#pragma once

#include <string>

namespace accelcal {

// The bytes of the file at `path`. Throws accelcal::Error "cannot open 'PATH': <reason>".
std::string ReadTextFile(const std::string& path);

}  // namespace accelcal

// Writing a whole file so that a crash never leaves it half written: the bytes go to PATH.tmp,
// which is then renamed over PATH (atomic on POSIX file systems).
#pragma once

#include <string>
#include <string_view>

namespace accelcal {

// Throws accelcal::Error "cannot write 'PATH': <reason>".
void WriteFileAtomically(const std::string& path, std::string_view bytes);

}  // namespace accelcal

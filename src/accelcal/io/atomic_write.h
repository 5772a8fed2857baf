// Writing a whole file so that a crash never leaves it half written: the bytes go to PATH.tmp,
// which is then renamed over PATH (atomic on POSIX file systems).
#pragma once

#include <string>
#include <string_view>

namespace accelcal {

// Throws accelcal::Error "cannot write 'PATH': <reason>" (a full disk: "No space left on
// device"), leaving PATH as it was and no PATH.tmp behind. A PATH that is not a regular file (a
// device such as /dev/stdout, a pipe) is written in place.
void WriteFileAtomically(const std::string& path, std::string_view bytes);

}  // namespace accelcal

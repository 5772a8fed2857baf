#include "accelcal/io/text_file.h"

#include "accelcal/io/detail/read_file.h"

namespace accelcal {

std::string ReadTextFile(const std::string& path) { return detail::ReadWholeFile(path); }

}  // namespace accelcal

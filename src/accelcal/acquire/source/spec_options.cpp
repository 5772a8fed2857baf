#include "accelcal/acquire/source/spec_options.h"

namespace accelcal {

SpecParts SplitSpecOptions(const std::string& body) {
  SpecParts parts;
  size_t from = 0;
  bool first = true;
  for (;;) {
    const size_t comma = body.find(',', from);
    const std::string piece = body.substr(from, comma - from);
    if (first) {
      parts.head = piece;
      first = false;
    } else {
      const size_t eq = piece.find('=');
      parts.options.push_back({piece.substr(0, eq), eq == std::string::npos ? "" : piece.substr(eq + 1),
                               eq != std::string::npos, piece});
    }
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return parts;
}

}  // namespace accelcal

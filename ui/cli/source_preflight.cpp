#include "cli/source_preflight.h"

#include <filesystem>

#include <fmt/core.h>

#include "accelcal/acquire/source/source_spec.h"
#include "accelcal/base/error.h"

namespace accelcal::cli {

void RefuseAbsentSerialPort(const std::string& spec) {
  const SourceSpec parsed = ParseSourceSpec(spec);
  if (parsed.kind != SourceKind::kSerial) return;
  std::error_code ec;
  if (std::filesystem::exists(parsed.path, ec)) return;
  throw Error(fmt::format("serial port {} does not exist: plug the adapter in or check the name "
                          "(ls /dev/ttyUSB* /dev/ttyACM*); no session was created or changed",
                          parsed.path));
}

}  // namespace accelcal::cli

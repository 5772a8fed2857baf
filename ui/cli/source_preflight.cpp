#include "cli/source_preflight.h"

#include <filesystem>

#include <fmt/core.h>

#include "accelcal/acquire/mavlink/mavlink_sensor_set.h"
#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/acquire/source/source_spec.h"
#include "accelcal/app/device/vehicle_session.h"
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

namespace {

std::vector<std::string> PrepareVehicleLink(MavlinkSource& vehicle, const std::string& choice, std::FILE* say,
                                            std::FILE* say_when_refused) {
  const VehiclePreparation prep = PrepareVehicleSource(
      vehicle, choice == "as-is" ? VehicleCalibrationChoice::kAsIs : VehicleCalibrationChoice::kUndo);
  std::FILE* out = prep.refused.empty() ? say : say_when_refused;
  if (out != nullptr)
    for (const std::string& line : prep.lines) fmt::print(out, "{}\n", line);
  if (!prep.refused.empty()) throw Error(prep.refused + "; no session was created or changed");
  return prep.lines;
}

}  // namespace

std::vector<std::string> PrepareVehicle(SampleSource& source, const std::string& choice, std::FILE* say,
                                        std::FILE* say_when_refused) {
  auto* vehicle = dynamic_cast<MavlinkSource*>(&source);
  if (vehicle == nullptr) return {};
  return PrepareVehicleLink(*vehicle, choice, say, say_when_refused);
}

std::vector<std::string> PrepareVehicle(SensorSetSource& set, const std::string& choice, std::FILE* say,
                                        std::FILE* say_when_refused) {
  auto* vehicle = dynamic_cast<MavlinkSensorSet*>(&set);
  if (vehicle == nullptr) return {};
  return PrepareVehicleLink(vehicle->instances(), choice, say, say_when_refused);
}

}  // namespace accelcal::cli

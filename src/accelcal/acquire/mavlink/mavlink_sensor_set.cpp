#include "accelcal/acquire/mavlink/mavlink_sensor_set.h"

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

constexpr std::size_t kMostImus = 3;  // IMU instances 0, 1, 2 (SCALED_IMU, SCALED_IMU2, SCALED_IMU3)

std::unique_ptr<MavlinkSource> OpenInstances(const std::string& spec, std::size_t sensors,
                                             const SourceOptions& options) {
  if (sensors == 0 || sensors > kMostImus)
    throw Error(fmt::format("{} sensors on '{}': a vehicle's IMU instances are 0, 1 and 2 (at most {} "
                            "sensors on one MAVLink link)", sensors, spec, kMostImus));
  MavlinkSourceSpec parsed = ParseMavlinkSpec(spec);
  if (spec.find(",imu=") != std::string::npos)
    throw Error(fmt::format("'{}' names one IMU (imu={}) but the session has {} sensors: leave imu= out, "
                            "sensor i is IMU instance i", spec, parsed.imu, sensors));
  std::vector<int> imus;
  for (std::size_t i = 0; i < sensors; ++i) imus.push_back(static_cast<int>(i));
  return std::make_unique<MavlinkSource>(std::move(parsed), options, std::move(imus));
}

}  // namespace

MavlinkSensorSet::MavlinkSensorSet(const std::string& spec, Fixture fixture, const SourceOptions& options)
    : fixture_(std::move(fixture)), source_(OpenInstances(spec, fixture_.sensors.size(), options)) {}

std::string MavlinkSensorSet::Describe() const {
  std::string text = source_->spec().Describe();
  if (const std::size_t at = text.find(",imu="); at != std::string::npos) text.erase(at, 6);  // ",imu=0"
  text += fmt::format(" (IMUs 0-{}:", source_->imu_count() - 1);
  for (std::size_t i = 0; i < fixture_.sensors.size(); ++i) text += (i ? ", " : " ") + fixture_.sensors[i].serial;
  return text + ")";
}

ReadResult MavlinkSensorSet::Read(double timeout_s, SensorSetSamples* out) {
  out->Resize(fixture_.sensors.size());
  return source_->ReadAll(timeout_s, &out->per_sensor);
}

}  // namespace accelcal

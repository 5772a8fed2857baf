#include "accelcal/io/detail/fixture_toml.h"

#include <cmath>
#include <optional>
#include <string>

#include <fmt/core.h>

namespace accelcal::detail {
namespace {

SensorAxis ReadFixtureAxis(TomlTableReader& r, std::string_view key, SensorAxis fallback) {
  if (!r.Has(key)) return fallback;
  const std::string text = r.String(key, std::nullopt);
  const std::optional<SensorAxis> axis = StringToSensorAxis(text);
  if (!axis) r.Fail(*r.Get(key), key, "expected one of +x -x +y -y +z -z, got '" + text + "'");
  return *axis;
}

}  // namespace

Eigen::Matrix3d ReadSensorToPlate(TomlTableReader& r, std::string_view key_x,
                                  std::string_view key_y) {
  const SensorAxis x = ReadFixtureAxis(r, key_x, SensorAxis::kPlusX);
  const SensorAxis y = ReadFixtureAxis(r, key_y, SensorAxis::kPlusY);
  if (std::abs(SensorAxisVector(x).dot(SensorAxisVector(y))) > 0.5) {
    r.FailKey(r.Has(key_y) ? key_y : key_x,
              fmt::format("the sensor's x ({}) and y ({}) must be perpendicular",
                          SensorAxisToString(x), SensorAxisToString(y)));
  }
  return SensorToPlate(x, y);
}

FixtureSensor ReadFixtureSensorFields(TomlTableReader& r) {
  FixtureSensor s;
  s.serial = r.String("serial", std::nullopt);
  if (s.serial.empty() || s.serial.find_first_of("\r\n\t,") != std::string::npos) {
    r.Fail(*r.Get("serial"), "serial", "must be one line of text, without commas or tabs");
  }
  s.sensor_to_plate = ReadSensorToPlate(r, "x", "y");
  s.offset_m = r.Vector3("offset_m", Eigen::Vector3d::Zero());
  return s;
}

}  // namespace accelcal::detail

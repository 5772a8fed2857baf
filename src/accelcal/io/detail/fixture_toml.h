// One fixture sensor's fields in TOML (serial, x, y, offset_m), shared by the fixture file
// ([[sensor]]) and a scenario's fixture ([[fixture.board]]).
#pragma once

#include <string_view>

#include "accelcal/base/fixture.h"
#include "accelcal/io/detail/toml_reader.h"

namespace accelcal::detail {

// A signed axis at `key_x`/`key_y` ("+x" ... "-z"), defaults +x and +y, into a rotation
// (sensor -> plate); refuses axes that are not perpendicular, at the key given.
Eigen::Matrix3d ReadSensorToPlate(TomlTableReader& r, std::string_view key_x,
                                  std::string_view key_y);

// serial (required; one line, no comma or tab), x, y, offset_m; not `source`.
FixtureSensor ReadFixtureSensorFields(TomlTableReader& r);

}  // namespace accelcal::detail

#include "accelcal/session/detail/sensor_rows.h"

#include <cmath>
#include <sstream>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"
#include "accelcal/session/detail/session_schema.h"
#include "accelcal/session/sensor_journal_view.h"

namespace accelcal::detail {
namespace {

template <typename Matrix>
std::string Numbers(const Matrix& m) {
  std::string text;
  for (int r = 0; r < m.rows(); ++r)
    for (int c = 0; c < m.cols(); ++c) text += fmt::format("{}{}", text.empty() ? "" : " ", m(r, c));
  return text;
}

template <typename Matrix>
bool ReadNumbers(const std::string& text, Matrix* m) {
  std::istringstream in(text);
  for (int r = 0; r < m->rows(); ++r)
    for (int c = 0; c < m->cols(); ++c)
      if (!(in >> (*m)(r, c))) return false;
  std::string rest;
  return !(in >> rest);
}

bool SameSensors(const Fixture& a, const Fixture& b) {
  if (a.name != b.name || a.sensors.size() != b.sensors.size()) return false;
  for (std::size_t i = 0; i < a.sensors.size(); ++i) {
    const FixtureSensor& x = a.sensors[i];
    const FixtureSensor& y = b.sensors[i];
    if (x.serial != y.serial || x.sensor_to_plate != y.sensor_to_plate ||
        x.offset_m != y.offset_m || x.source != y.source)
      return false;
  }
  return a.placement_u_rad == b.placement_u_rad ||
         (std::isnan(a.placement_u_rad) && std::isnan(b.placement_u_rad));
}

}  // namespace

void InsertSensorRows(SqliteDb& db, const Fixture& sensors, const std::string& recorded_utc) {
  if (std::string why = sensors.Validate(); !why.empty())
    throw Error(fmt::format("session {}: its sensors: {}", db.path(), why));
  if (const std::optional<Fixture> have = ReadSensorRows(db)) {
    if (SameSensors(*have, sensors)) return;
    throw Error(fmt::format("session {} already holds other sensors ({}, ...): a session's "
                            "sensors never change", db.path(), have->sensors.front().serial));
  }
  const std::int64_t beyond = db.QueryInt(
      fmt::format("SELECT count(*) FROM captures WHERE sensor >= {}", sensors.sensors.size()));
  if (beyond > 0)
    throw Error(fmt::format("session {} has captures of a sensor beyond the {} given",
                            db.path(), sensors.sensors.size()));
  for (std::size_t i = 0; i < sensors.sensors.size(); ++i) {
    const FixtureSensor& s = sensors.sensors[i];
    SqliteStatement(db, "INSERT INTO sensors (sensor, serial, sensor_to_plate, offset_m, source, "
                        "fixture_name, recorded_utc) VALUES (?, ?, ?, ?, ?, ?, ?)")
        .Bind(1, static_cast<std::int64_t>(i)).Bind(2, s.serial)
        .Bind(3, Numbers(s.sensor_to_plate)).Bind(4, Numbers(s.offset_m.transpose()))
        .Bind(5, s.source).Bind(6, sensors.name).Bind(7, recorded_utc).Run();
  }
  // The plate's placement uncertainty is one figure of the whole set: an input of its pseudo
  // step, so that version 7's sensors table holds as it is.
  if (std::isfinite(sensors.placement_u_rad))
    SqliteStatement(db, "INSERT OR REPLACE INTO inputs (step_id, key, value, recorded_utc) "
                        "VALUES (?, ?, ?, ?)")
        .Bind(1, kSensorSetStep).Bind(2, kSensorSetPlacementKey)
        .Bind(3, fmt::format("{}", sensors.placement_u_rad * 180.0 / M_PI)).Bind(4, recorded_utc).Run();
}

std::optional<Fixture> ReadSensorRows(SqliteDb& db) {
  if (!HasTable(db, "sensors")) return std::nullopt;
  SqliteStatement rows(db, "SELECT sensor, serial, sensor_to_plate, offset_m, source, fixture_name "
                           "FROM sensors ORDER BY sensor");
  Fixture fixture;
  while (rows.Step()) {
    const std::int64_t index = rows.ColumnInt(0);
    FixtureSensor s;
    s.serial = rows.ColumnText(1);
    Eigen::Matrix<double, 1, 3> offset;
    if (index != static_cast<std::int64_t>(fixture.sensors.size()) ||
        !ReadNumbers(rows.ColumnText(2), &s.sensor_to_plate) ||
        !ReadNumbers(rows.ColumnText(3), &offset))
      throw Error(fmt::format("session {} is damaged: its sensor row {} cannot be read",
                              db.path(), index));
    s.offset_m = offset.transpose();
    s.source = rows.ColumnText(4);
    fixture.name = rows.ColumnText(5);
    fixture.sensors.push_back(std::move(s));
  }
  if (fixture.sensors.empty()) return std::nullopt;
  SqliteStatement placement(db, "SELECT value FROM inputs WHERE step_id = ? AND key = ?");
  placement.Bind(1, kSensorSetStep).Bind(2, kSensorSetPlacementKey);
  if (placement.Step()) {
    double deg = kNaN;
    if (!ParseDouble(placement.ColumnText(0), &deg) || !std::isfinite(deg) || deg < 0.0)
      throw Error(fmt::format("session {} is damaged: its fixture's placement uncertainty '{}' "
                              "is not an angle", db.path(), placement.ColumnText(0)));
    fixture.placement_u_rad = deg * M_PI / 180.0;
  }
  return fixture;
}

}  // namespace accelcal::detail

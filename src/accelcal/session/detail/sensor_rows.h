// The session's sensors as rows of the `sensors` table (schema version 7, issue 31): one per
// sensor, its index the captures' `sensor`. The rotation is stored as its 9 numbers row by row,
// the offset as 3 numbers (m), separated by blanks, each in the shortest form that reads back
// exactly.
#pragma once

#include <optional>
#include <string>

#include "accelcal/base/fixture.h"
#include "accelcal/session/detail/sqlite_db.h"

namespace accelcal::detail {

// Inside the caller's transaction. The same sensors again: nothing to do. Throws
// accelcal::Error when other sensors are recorded already, when `sensors` is not valid
// (Fixture::Validate), or when a capture of a sensor index it does not have exists.
void InsertSensorRows(SqliteDb& db, const Fixture& sensors, const std::string& recorded_utc);
// nullopt when none are recorded (a one-sensor session) or the file predates the table.
// Throws accelcal::Error naming the row when one cannot be read.
std::optional<Fixture> ReadSensorRows(SqliteDb& db);

}  // namespace accelcal::detail

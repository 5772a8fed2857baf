// Captures as rows of the `captures` table (statistics columns plus the sample blob).
#pragma once

#include <string>
#include <vector>

#include "accelcal/session/detail/sqlite_db.h"
#include "accelcal/session/session_journal.h"

namespace accelcal::detail {

// Inserts inside the caller's transaction. Throws accelcal::Error when `step_id` already has a
// capture (the UNIQUE constraint backs this up).
void InsertCaptureRow(SqliteDb& db, const std::string& step_id, const Capture& capture,
                      const std::string& recorded_utc);
// All captures in recording order. Throws accelcal::Error when a row is damaged (its sample
// count differs from n).
std::vector<JournalCapture> ReadCaptureRows(SqliteDb& db);

}  // namespace accelcal::detail

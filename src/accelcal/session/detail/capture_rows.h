// Captures as rows of the `captures` table (statistics columns plus the sample blob).
#pragma once

#include <string>
#include <vector>

#include "accelcal/session/detail/sqlite_db.h"
#include "accelcal/session/session_journal.h"

namespace accelcal::detail {

// `sensor`: which of the session's sensors (0: the first, a one-sensor session's only).
void InsertCaptureRow(SqliteDb& db, const std::string& step_id, const Capture& capture,
                      const std::string& recorded_utc, int sensor = 0);
// Inserts inside the caller's transaction, with the row's checksum (row_checksum.h). Throws
// accelcal::Error when `step_id` already has an intact capture (the UNIQUE constraint backs this
// up); a damaged one (CaptureRows::damaged) is replaced, so that a resumed wizard can take it
// again.
struct CaptureRows {
  std::vector<JournalCapture> intact;   // in recording order
  std::vector<DamagedCapture> damaged;  // in recording order
};
// Every capture, checked: a row whose checksum (version 4 and later) does not match, whose
// sample count differs from n, or whose samples do not decode is damaged. Rows of a file older
// than version 4 (read-only opens) have no checksum: only the sample count is checked.
// `sensor` >= 0: that sensor's only; -1: every sensor's.
CaptureRows ReadCaptureRows(SqliteDb& db, int sensor);
// Marks every sensor's intact capture of `step_id` superseded by the one of `by_step_id` (a redo), inside
// the caller's transaction. Throws accelcal::Error when `step_id` has no intact capture or its
// capture is already superseded.
void MarkCaptureRowSuperseded(SqliteDb& db, const std::string& step_id, const std::string& by_step_id);

}  // namespace accelcal::detail

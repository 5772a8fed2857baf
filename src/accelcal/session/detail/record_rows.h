// Record chunks and gaps as rows of `record_chunks` and `record_gaps` (session_schema.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "accelcal/session/detail/sqlite_db.h"
#include "accelcal/session/session_journal.h"

namespace accelcal::detail {

// Inserts the chunk (and its gap_before) inside the caller's transaction, with its checksum,
// after checking it against what the record holds (CheckRecordChunk).
void InsertRecordChunk(SqliteDb& db, const std::string& step_id, const RecordChunk& chunk,
                       const std::string& recorded_utc);
// The record of `step_id` so far, from the rows' columns (no sample is decoded).
RecordSummary ReadRecordSummary(SqliteDb& db, const std::string& step_id);
// Each chunk in order, decoded one at a time, checked: a chunk whose checksum (version 4) does
// not match, whose sample count differs from n or whose blob is not whole samples is left out,
// and the next one carries the hole as its gap_before, the damage in its reason; damaged last
// chunks are the last good chunk's gap_after (it is visited once the next row is read: two
// chunks in memory at most).
void VisitRecordRows(SqliteDb& db, const std::string& step_id,
                     const std::function<void(const RecordChunk&)>& visit);
// Steps with record chunks, by their first chunk's order of insertion.
std::vector<std::string> ReadRecordSteps(SqliteDb& db);

}  // namespace accelcal::detail

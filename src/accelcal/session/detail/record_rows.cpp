#include "accelcal/session/detail/record_rows.h"

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/session/detail/sample_blob.h"
#include "accelcal/session/detail/session_schema.h"

namespace accelcal::detail {
namespace {

// A version-1 session opened read-only has no record tables: it has no records.
bool HasRecordTables(SqliteDb& db) { return HasTable(db, "record_chunks"); }

}  // namespace

void InsertRecordChunk(SqliteDb& db, const std::string& step_id, const RecordChunk& chunk,
                       const std::string& recorded_utc) {
  CheckRecordChunk(step_id, chunk, ReadRecordSummary(db, step_id));
  SqliteStatement insert(db, "INSERT INTO record_chunks (step_id, chunk_index, n, t_first_s, "
                             "t_last_s, wall_end_s, samples, recorded_utc) VALUES (?,?,?,?,?,?,?,?)");
  insert.Bind(1, step_id).Bind(2, static_cast<std::int64_t>(chunk.index));
  insert.Bind(3, static_cast<std::int64_t>(chunk.samples.size()));
  insert.Bind(4, chunk.samples.front().t_s).Bind(5, chunk.samples.back().t_s);
  insert.Bind(6, chunk.wall_end_s).BindBlob(7, EncodeSamples(chunk.samples)).Bind(8, recorded_utc);
  insert.Run();
  if (!chunk.gap_before) return;
  SqliteStatement gap(db, "INSERT INTO record_gaps (step_id, before_chunk, t_start_s, t_end_s, "
                          "reason, recorded_utc) VALUES (?,?,?,?,?,?)");
  gap.Bind(1, step_id).Bind(2, static_cast<std::int64_t>(chunk.index));
  gap.Bind(3, chunk.gap_before->t_start_s).Bind(4, chunk.gap_before->t_end_s);
  gap.Bind(5, chunk.gap_before->reason).Bind(6, recorded_utc);
  gap.Run();
}

RecordSummary ReadRecordSummary(SqliteDb& db, const std::string& step_id) {
  RecordSummary s;
  if (!HasRecordTables(db)) return s;
  SqliteStatement chunks(db, "SELECT count(*), coalesce(sum(n), 0), min(t_first_s), max(t_last_s) "
                             "FROM record_chunks WHERE step_id = ?");
  chunks.Bind(1, step_id);
  if (chunks.Step()) {
    s.num_chunks = static_cast<long>(chunks.ColumnInt(0));
    s.num_samples = static_cast<long>(chunks.ColumnInt(1));
    s.t_first_s = chunks.ColumnDouble(2);
    s.t_last_s = chunks.ColumnDouble(3);
  }
  SqliteStatement last(db, "SELECT wall_end_s FROM record_chunks WHERE step_id = ? "
                           "ORDER BY chunk_index DESC LIMIT 1");
  last.Bind(1, step_id);
  if (last.Step()) s.last_wall_end_s = last.ColumnDouble(0);
  SqliteStatement gaps(db, "SELECT count(*), coalesce(sum(t_end_s - t_start_s), 0) FROM "
                           "record_gaps WHERE step_id = ?");
  gaps.Bind(1, step_id);
  if (gaps.Step()) {
    s.num_gaps = static_cast<long>(gaps.ColumnInt(0));
    s.gaps_s = gaps.ColumnDouble(1);
  }
  return s;
}

void VisitRecordRows(SqliteDb& db, const std::string& step_id,
                     const std::function<void(const RecordChunk&)>& visit) {
  if (!HasRecordTables(db)) return;
  SqliteStatement rows(db,
                       "SELECT c.chunk_index, c.n, c.wall_end_s, c.samples, g.t_start_s, "
                       "g.t_end_s, g.reason FROM record_chunks c LEFT JOIN record_gaps g "
                       "ON g.step_id = c.step_id AND g.before_chunk = c.chunk_index "
                       "WHERE c.step_id = ? ORDER BY c.chunk_index");
  rows.Bind(1, step_id);
  while (rows.Step()) {
    RecordChunk chunk;
    chunk.index = static_cast<long>(rows.ColumnInt(0));
    chunk.wall_end_s = rows.ColumnDouble(2);
    chunk.samples = DecodeSamples(rows.ColumnBlob(3));
    if (static_cast<std::int64_t>(chunk.samples.size()) != rows.ColumnInt(1))
      throw Error(fmt::format("session {}: record '{}' chunk {} is damaged: {} samples stored, "
                              "{} expected", db.path(), step_id, chunk.index, chunk.samples.size(),
                              rows.ColumnInt(1)));
    if (!rows.ColumnIsNull(4))
      chunk.gap_before = RecordGap{rows.ColumnDouble(4), rows.ColumnDouble(5), rows.ColumnText(6)};
    visit(chunk);
  }
}

std::vector<std::string> ReadRecordSteps(SqliteDb& db) {
  std::vector<std::string> out;
  if (!HasRecordTables(db)) return out;
  SqliteStatement rows(db, "SELECT step_id FROM record_chunks WHERE chunk_index = 0 ORDER BY rowid");
  while (rows.Step()) out.push_back(rows.ColumnText(0));
  return out;
}

}  // namespace accelcal::detail

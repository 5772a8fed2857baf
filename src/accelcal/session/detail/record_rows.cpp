#include "accelcal/session/detail/record_rows.h"

#include <cmath>
#include <optional>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/session/detail/row_checksum.h"
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
  SqliteStatement statement(db, "INSERT INTO record_chunks (step_id, chunk_index, n, t_first_s, "
                                "t_last_s, wall_end_s, samples, recorded_utc, checksum) "
                                "VALUES (?,?,?,?,?,?,?,?,?)");
  ChecksummedInsert insert(statement);  // the columns in kChunkChecksumColumns' order
  insert.Add(step_id).Add(static_cast<std::int64_t>(chunk.index));
  insert.Add(static_cast<std::int64_t>(chunk.samples.size()));
  insert.Add(chunk.samples.front().t_s).Add(chunk.samples.back().t_s).Add(chunk.wall_end_s);
  insert.AddBlob(EncodeSamples(chunk.samples)).Add(recorded_utc);
  insert.BindChecksum();
  statement.Run();
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

namespace {

// Columns 0..7 are those of kChunkChecksumColumns, 8 the checksum (NULL in a file older than
// version 4, read as it is), 9..11 the gap before the chunk.
constexpr int kChunkIndex = 1, kChunkN = 2, kChunkTLast = 4, kChunkWallEnd = 5, kChunkSamples = 6,
              kChunkChecksum = 8, kChunkGapStart = 9;

std::string SelectSql(bool has_checksum) {
  return fmt::format("SELECT c.step_id, c.chunk_index, c.n, c.t_first_s, c.t_last_s, c.wall_end_s, "
                     "c.samples, c.recorded_utc, {}, g.t_start_s, g.t_end_s, g.reason "
                     "FROM record_chunks c LEFT JOIN record_gaps g ON g.step_id = c.step_id AND "
                     "g.before_chunk = c.chunk_index WHERE c.step_id = ? ORDER BY c.chunk_index",
                     has_checksum ? "c.checksum" : "NULL");
}

// The chunk of the current row, or what is wrong with it.
std::string ReadChunk(const SqliteStatement& row, bool has_checksum, RecordChunk* chunk) {
  if (has_checksum) {
    if (std::string problem = ChecksumProblem(row, 0, kChunkChecksumColumnCount, kChunkChecksum);
        !problem.empty())
      return problem;
  }
  chunk->index = static_cast<long>(row.ColumnInt(kChunkIndex));
  chunk->wall_end_s = row.ColumnDouble(kChunkWallEnd);
  try {
    chunk->samples = DecodeSamples(row.ColumnBlob(kChunkSamples));
  } catch (const Error& e) {
    return e.what();
  }
  if (static_cast<std::int64_t>(chunk->samples.size()) != row.ColumnInt(kChunkN) || chunk->samples.empty())
    return fmt::format("{} samples stored, {} expected", chunk->samples.size(), row.ColumnInt(kChunkN));
  if (!row.ColumnIsNull(kChunkGapStart))
    chunk->gap_before = RecordGap{row.ColumnDouble(kChunkGapStart), row.ColumnDouble(kChunkGapStart + 1),
                                  row.ColumnText(kChunkGapStart + 2)};
  return "";
}

// The hole that damaged chunks leave before `chunk`, merged with the gap it already has.
void AddDamageGap(const std::string& damage, double last_good_t_s, RecordChunk* chunk) {
  const double t_end_s = chunk->samples.front().t_s;
  RecordGap gap{std::isfinite(last_good_t_s) ? last_good_t_s : t_end_s, t_end_s, damage};
  if (chunk->gap_before) gap.reason += "; " + chunk->gap_before->reason;
  chunk->gap_before = gap;
}

// The hole that damaged last chunks leave after the last good one: to the end the damaged row
// states (its t_last_s column, unverified: used only when it lies after the last good sample),
// or of no length when it states none.
void AddEndGap(const std::string& damage, double damaged_t_last_s, RecordChunk* chunk) {
  const double t_start_s = chunk->samples.back().t_s;
  const double t_end_s = std::isfinite(damaged_t_last_s) && damaged_t_last_s > t_start_s ? damaged_t_last_s : t_start_s;
  chunk->gap_after = RecordGap{t_start_s, t_end_s, damage};
}

}  // namespace

void VisitRecordRows(SqliteDb& db, const std::string& step_id,
                     const std::function<void(const RecordChunk&)>& visit) {
  if (!HasRecordTables(db)) return;
  const bool has_checksum = HasRowChecksums(db);
  SqliteStatement rows(db, SelectSql(has_checksum));
  rows.Bind(1, step_id);
  std::string damage;  // of the chunks left out since the last good one
  double damaged_t_last_s = std::nan("");  // as the last damaged row states it
  double last_good_t_s = std::nan("");
  // The last good chunk is visited once the row after it is read: when the rows after it are
  // all damaged, it carries their hole as its gap_after.
  std::optional<RecordChunk> held;
  while (rows.Step()) {
    RecordChunk chunk;
    const std::string problem = ReadChunk(rows, has_checksum, &chunk);
    if (!problem.empty()) {
      damage += fmt::format("{}chunk {} is damaged in the session file ({}): left out",
                            damage.empty() ? "" : "; ", rows.ColumnInt(kChunkIndex), problem);
      damaged_t_last_s = rows.ColumnDouble(kChunkTLast);
      continue;
    }
    if (!damage.empty()) AddDamageGap(damage, last_good_t_s, &chunk);
    damage.clear();
    last_good_t_s = chunk.samples.back().t_s;
    if (held) visit(*held);
    held = std::move(chunk);
  }
  if (!held) return;  // no good chunk: nothing to read (RecordSummary still counts the rows)
  if (!damage.empty()) AddEndGap(damage, damaged_t_last_s, &*held);
  visit(*held);
}

std::vector<std::string> ReadRecordSteps(SqliteDb& db) {
  std::vector<std::string> out;
  if (!HasRecordTables(db)) return out;
  SqliteStatement rows(db, "SELECT step_id FROM record_chunks WHERE chunk_index = 0 ORDER BY rowid");
  while (rows.Step()) out.push_back(rows.ColumnText(0));
  return out;
}

}  // namespace accelcal::detail

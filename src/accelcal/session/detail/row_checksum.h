// A checksum per stored capture and per record chunk (schema version 4), so that a file damaged
// after it was written (a flipped bit on a disk, a bad copy) is caught instead of read as data.
//
// The checksum covers the row's columns as SQLite gives them back (type and value; text and
// blobs byte for byte). The writer computes it from the values it binds (ChecksummedInsert,
// which stores them as they will read back), and a migration from the rows of older files.
// Algorithm: 64-bit FNV-1a (http://www.isthe.com/chongo/tech/comp/fnv/) over a tagged encoding
// of each column. It is not a defence against someone who edits the file on purpose (nothing
// inside the file could be): it catches accidental damage, with a chance of 2^-64 of missing it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/session/detail/sqlite_db.h"

namespace accelcal::detail {

// The columns each table's checksum covers, in this order (every column but the checksum).
// Versions 4 to 6 (a file read as it is; the version-7 migration checks them).
inline constexpr const char* kCaptureChecksumColumnsV4 =
    "step_id, capture_id, kind, label, radius_m, rpm, up_axis, rejection_reason, n, "
    "mean_x_counts, mean_y_counts, mean_z_counts, comoment_xx_counts2, comoment_xy_counts2, "
    "comoment_xz_counts2, comoment_yy_counts2, comoment_yz_counts2, comoment_zz_counts2, "
    "t_first_s, t_last_s, mean_temp_c, samples, recorded_utc";
inline constexpr int kCaptureChecksumColumnCountV4 = 23;
// Version 7: the same and the sensor.
inline constexpr const char* kCaptureChecksumColumns =
    "step_id, capture_id, kind, label, radius_m, rpm, up_axis, rejection_reason, n, "
    "mean_x_counts, mean_y_counts, mean_z_counts, comoment_xx_counts2, comoment_xy_counts2, "
    "comoment_xz_counts2, comoment_yy_counts2, comoment_yz_counts2, comoment_zz_counts2, "
    "t_first_s, t_last_s, mean_temp_c, samples, recorded_utc, sensor";
inline constexpr int kCaptureChecksumColumnCount = 24;
inline constexpr const char* kChunkChecksumColumns =
    "step_id, chunk_index, n, t_first_s, t_last_s, wall_end_s, samples, recorded_utc";
inline constexpr int kChunkChecksumColumnCount = 8;

// Binds an INSERT's values to parameters 1, 2, ... in order, computing their checksum as
// ChecksumOfColumns computes it when the row is read back; then BindChecksum() binds it to the
// next parameter. Borrows `insert`.
class ChecksummedInsert {
 public:
  explicit ChecksummedInsert(SqliteStatement& insert) : insert_(insert) {}
  ChecksummedInsert& Add(const std::string& text);
  ChecksummedInsert& Add(std::int64_t value);
  ChecksummedInsert& Add(int value) { return Add(static_cast<std::int64_t>(value)); }
  // NaN is stored as NULL, and -0.0 as 0.0 (SQLite stores a REAL without fraction as an
  // integer: its sign would not come back).
  ChecksummedInsert& Add(double value);
  ChecksummedInsert& AddNull();
  ChecksummedInsert& AddBlob(const std::vector<unsigned char>& bytes);
  void BindChecksum();

 private:
  SqliteStatement& insert_;  // borrowed
  int next_ = 1;
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;  // FNV-1a state (offset basis)
};

// The checksum of columns [first, first + count) of the current row of `row`.
std::int64_t ChecksumOfColumns(const SqliteStatement& row, int first, int count);

// Computes and stores the checksum of the row `rowid` of `table` (inside the caller's
// transaction).
void StoreRowChecksum(SqliteDb& db, const std::string& table, const std::string& columns,
                      std::int64_t rowid);
// Computes and stores the checksum of every row of `table` (a migration step).
void StoreAllRowChecksums(SqliteDb& db, const std::string& table, const std::string& columns);

// Empty when column `checksum_index` of `row` holds the checksum of columns [first, first +
// count), else what is wrong ("its checksum does not match what it holds", "it has no
// checksum").
std::string ChecksumProblem(const SqliteStatement& row, int first, int count, int checksum_index);

// True when `table` has the column `column`.
bool HasColumn(SqliteDb& db, const std::string& table, const std::string& column);
// True when the file's rows carry checksums (schema version 4 and later; an older file opened
// read-only is read as it is).
bool HasRowChecksums(SqliteDb& db);

}  // namespace accelcal::detail

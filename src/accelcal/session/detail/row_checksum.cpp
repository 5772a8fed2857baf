#include "accelcal/session/detail/row_checksum.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string_view>
#include <cstring>
#include <vector>

#include <fmt/core.h>

namespace accelcal::detail {
namespace {

constexpr std::uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ULL;
constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;

void AddBytes(std::uint64_t* hash, const void* data, size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::uint64_t h = *hash;
  for (size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * kFnvPrime;
  *hash = h;
}

void AddU64(std::uint64_t* hash, std::uint64_t v) { AddBytes(hash, &v, sizeof v); }

// One column: a tag for its type, then its value (lengths included, so that columns cannot run
// into each other). The tags are SqliteStatement::ColumnKind's.
using Kind = SqliteStatement::ColumnKind;
void AddTag(std::uint64_t* hash, Kind kind) { AddU64(hash, static_cast<std::uint64_t>(kind)); }
void AddSized(std::uint64_t* hash, std::string_view bytes) {
  AddU64(hash, bytes.size());
  AddBytes(hash, bytes.data(), bytes.size());
}

void AddColumn(std::uint64_t* hash, const SqliteStatement& row, int index) {
  const Kind kind = row.ColumnKindOf(index);
  AddTag(hash, kind);
  switch (kind) {
    case Kind::kNull: return;
    case Kind::kInteger: return AddU64(hash, static_cast<std::uint64_t>(row.ColumnInt(index)));
    case Kind::kReal: return AddU64(hash, std::bit_cast<std::uint64_t>(row.ColumnDouble(index)));
    case Kind::kText:
    case Kind::kBlob: return AddSized(hash, row.ColumnBytes(index));
  }
}

}  // namespace

ChecksummedInsert& ChecksummedInsert::Add(const std::string& text) {
  insert_.Bind(next_++, text);
  AddTag(&hash_, Kind::kText);
  AddSized(&hash_, text);
  return *this;
}

ChecksummedInsert& ChecksummedInsert::Add(std::int64_t value) {
  insert_.Bind(next_++, value);
  AddTag(&hash_, Kind::kInteger);
  AddU64(&hash_, static_cast<std::uint64_t>(value));
  return *this;
}

ChecksummedInsert& ChecksummedInsert::Add(double value) {
  if (std::isnan(value)) return AddNull();
  if (value == 0.0) value = 0.0;  // -0.0 reads back as 0.0
  insert_.Bind(next_++, value);
  AddTag(&hash_, Kind::kReal);
  AddU64(&hash_, std::bit_cast<std::uint64_t>(value));
  return *this;
}

ChecksummedInsert& ChecksummedInsert::AddNull() {
  insert_.BindNull(next_++);
  AddTag(&hash_, Kind::kNull);
  return *this;
}

ChecksummedInsert& ChecksummedInsert::AddBlob(const std::vector<unsigned char>& bytes) {
  insert_.BindBlob(next_++, bytes);
  AddTag(&hash_, Kind::kBlob);
  AddSized(&hash_, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  return *this;
}

void ChecksummedInsert::BindChecksum() { insert_.Bind(next_++, static_cast<std::int64_t>(hash_)); }

std::int64_t ChecksumOfColumns(const SqliteStatement& row, int first, int count) {
  std::uint64_t hash = kFnvOffsetBasis;
  for (int i = first; i < first + count; ++i) AddColumn(&hash, row, i);
  return static_cast<std::int64_t>(hash);
}

void StoreRowChecksum(SqliteDb& db, const std::string& table, const std::string& columns,
                      std::int64_t rowid) {
  SqliteStatement row(db, fmt::format("SELECT {} FROM {} WHERE rowid = ?", columns, table));
  row.Bind(1, rowid);
  if (!row.Step()) return;
  const int count = static_cast<int>(std::count(columns.begin(), columns.end(), ',')) + 1;
  SqliteStatement(db, fmt::format("UPDATE {} SET checksum = ? WHERE rowid = ?", table))
      .Bind(1, ChecksumOfColumns(row, 0, count)).Bind(2, rowid).Run();
}

void StoreAllRowChecksums(SqliteDb& db, const std::string& table, const std::string& columns) {
  std::vector<std::int64_t> rowids;
  SqliteStatement rows(db, fmt::format("SELECT rowid FROM {}", table));
  while (rows.Step()) rowids.push_back(rows.ColumnInt(0));
  for (std::int64_t rowid : rowids) StoreRowChecksum(db, table, columns, rowid);
}

std::string ChecksumProblem(const SqliteStatement& row, int first, int count, int checksum_index) {
  if (row.ColumnIsNull(checksum_index)) return "it has no checksum";
  if (row.ColumnInt(checksum_index) != ChecksumOfColumns(row, first, count))
    return "its checksum does not match what it holds";
  return "";
}

bool HasColumn(SqliteDb& db, const std::string& table, const std::string& column) {
  SqliteStatement query(db, fmt::format("SELECT 1 FROM pragma_table_info('{}') WHERE name = ?", table));
  query.Bind(1, column);
  return query.Step();
}

}  // namespace accelcal::detail

namespace accelcal::detail {

bool HasRowChecksums(SqliteDb& db) { return db.QueryInt("PRAGMA user_version") >= 4; }

}  // namespace accelcal::detail

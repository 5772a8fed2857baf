#include "accelcal/session/detail/capture_rows.h"

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/session/detail/row_checksum.h"
#include "accelcal/session/detail/sample_blob.h"

namespace accelcal::detail {
namespace {

constexpr const char* kInsert =
    "INSERT INTO captures (step_id, capture_id, kind, label, radius_m, rpm, up_axis, "
    "rejection_reason, n, mean_x_counts, mean_y_counts, mean_z_counts, comoment_xx_counts2, "
    "comoment_xy_counts2, comoment_xz_counts2, comoment_yy_counts2, comoment_yz_counts2, "
    "comoment_zz_counts2, t_first_s, "
    "t_last_s, mean_temp_c, samples, recorded_utc, sensor, checksum) "
    "VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)";

// Column 0 is seq, columns 1..24 those of kCaptureChecksumColumns (24: the sensor), column 25
// the checksum, 26 superseded_by. A file older than version 7 (read read-only, as it is) has no
// sensor (its select gives 0: its one sensor) and a checksum over the first 23; one older than
// version 4 has no checksum, and versions 1 and 2 named the co-moments otherwise: its select
// fills the columns it does not read with NULL.
constexpr int kFirst = 1;
constexpr int kStepId = 1, kCaptureId = 2, kKind = 3, kLabel = 4, kRadius = 5, kRpm = 6,
              kUpAxis = 7, kRejection = 8, kN = 9, kSamples = 22;
constexpr int kSensor = kFirst + kCaptureChecksumColumnCount - 1;
constexpr int kChecksum = kFirst + kCaptureChecksumColumnCount;
constexpr int kSupersededBy = kChecksum + 1;  // version 5; NULL in older files read as they are

// What the file's captures table has (by its version).
struct CaptureLayout {
  bool has_checksum = true;
  bool has_superseded = true;
  bool has_sensor = true;

  int checksummed_columns() const {
    return has_sensor ? kCaptureChecksumColumnCount : kCaptureChecksumColumnCountV4;
  }
};

CaptureLayout LayoutOf(SqliteDb& db) {
  const bool has_checksum = HasRowChecksums(db);
  return {has_checksum, HasColumn(db, "captures", "superseded_by"),
          has_checksum && HasColumn(db, "captures", "sensor")};
}

std::string SelectSql(const CaptureLayout& layout, const std::string& where) {
  const char* superseded = layout.has_superseded ? "superseded_by" : "NULL";
  if (layout.has_sensor)
    return fmt::format("SELECT seq, {}, checksum, {} FROM captures {} ORDER BY seq",
                       kCaptureChecksumColumns, superseded, where);
  if (layout.has_checksum)
    return fmt::format("SELECT seq, {}, 0, checksum, {} FROM captures {} ORDER BY seq",
                       kCaptureChecksumColumnsV4, superseded, where);
  return fmt::format("SELECT seq, step_id, capture_id, kind, label, radius_m, rpm, up_axis, "
                     "rejection_reason, n, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, "
                     "NULL, NULL, NULL, samples, recorded_utc, 0, NULL, {} FROM captures {} "
                     "ORDER BY seq",
                     superseded, where);
}

void AddStats(ChecksummedInsert& insert, const CaptureStats& stats) {
  insert.Add(static_cast<std::int64_t>(stats.n));
  for (int i = 0; i < 3; ++i) insert.Add(stats.mean_counts(i));
  const Eigen::Matrix3d& c = stats.comoment_counts2;
  insert.Add(c(0, 0)).Add(c(0, 1)).Add(c(0, 2)).Add(c(1, 1)).Add(c(1, 2)).Add(c(2, 2));
  insert.Add(stats.t_first_s).Add(stats.t_last_s).Add(stats.mean_temp_c);
}

// Throws accelcal::Error (without the path: the caller names the row) when the row cannot be a
// capture.
Capture CaptureFromRow(const SqliteStatement& row) {
  Capture c;
  c.id = static_cast<int>(row.ColumnInt(kCaptureId));
  const std::string kind = row.ColumnText(kKind);
  const std::optional<CaptureKind> parsed = StringToCaptureKind(kind);
  if (!parsed) throw Error(fmt::format("unknown kind '{}'", kind));
  c.kind = *parsed;
  c.label = row.ColumnText(kLabel);
  c.radius_m = row.ColumnDouble(kRadius);
  c.rpm = row.ColumnDouble(kRpm);
  if (!row.ColumnIsNull(kUpAxis)) c.up_axis = StringToSensorAxis(row.ColumnText(kUpAxis));
  c.rejection_reason = row.ColumnText(kRejection);
  c.samples = DecodeSamples(row.ColumnBlob(kSamples));
  const std::int64_t n = row.ColumnInt(kN);
  if (static_cast<std::int64_t>(c.samples.size()) != n)
    throw Error(fmt::format("{} samples stored, {} expected", c.samples.size(), n));
  return c;
}

// Reads the current row into `out`: intact or damaged.
void ReadRow(const SqliteStatement& row, const CaptureLayout& layout, CaptureRows* out) {
  DamagedCapture damaged{row.ColumnText(kStepId), row.ColumnText(kLabel), ""};
  damaged.sensor = static_cast<int>(row.ColumnInt(kSensor));
  if (layout.has_checksum)
    damaged.problem = ChecksumProblem(row, kFirst, layout.checksummed_columns(), kChecksum);
  if (damaged.problem.empty()) {
    try {
      JournalCapture intact{damaged.step_id, CaptureFromRow(row), ""};
      intact.sensor = damaged.sensor;
      if (!row.ColumnIsNull(kSupersededBy)) intact.superseded_by = row.ColumnText(kSupersededBy);
      out->intact.push_back(std::move(intact));
      return;
    } catch (const Error& e) {
      damaged.problem = e.what();
    }
  }
  out->damaged.push_back(std::move(damaged));
}

// `where` filters with up to two parameters: the step id (when not empty), then the sensor
// (when >= 0); a file without the sensor column holds sensor 0's only.
CaptureRows ReadRows(SqliteDb& db, const std::string& step_id, int sensor) {
  const CaptureLayout layout = LayoutOf(db);
  std::string where;
  if (!step_id.empty()) where = "WHERE step_id = ?";
  if (sensor >= 0 && layout.has_sensor) where += where.empty() ? "WHERE sensor = ?" : " AND sensor = ?";
  CaptureRows out;
  if (sensor > 0 && !layout.has_sensor) return out;
  SqliteStatement rows(db, SelectSql(layout, where));
  int next = 1;
  if (!step_id.empty()) rows.Bind(next++, step_id);
  if (sensor >= 0 && layout.has_sensor) rows.Bind(next++, static_cast<std::int64_t>(sensor));
  while (rows.Step()) ReadRow(rows, layout, &out);
  return out;
}

// Throws when `step_id` has an intact capture of `sensor`; deletes a damaged one (it is taken
// again).
void MakeRoomFor(SqliteDb& db, const std::string& step_id, int sensor) {
  const CaptureRows existing = ReadRows(db, step_id, sensor);
  if (!existing.intact.empty())
    throw Error(fmt::format("session {}: step '{}' already has an accepted capture{}", db.path(),
                            step_id, sensor > 0 ? fmt::format(" of sensor {}", sensor + 1) : ""));
  if (!existing.damaged.empty())
    SqliteStatement(db, "DELETE FROM captures WHERE step_id = ? AND sensor = ?")
        .Bind(1, step_id).Bind(2, static_cast<std::int64_t>(sensor)).Run();
}

}  // namespace

void InsertCaptureRow(SqliteDb& db, const std::string& step_id, const Capture& capture,
                      const std::string& recorded_utc, int sensor) {
  if (sensor < 0) throw Error(fmt::format("session {}: sensor {} does not exist", db.path(), sensor));
  MakeRoomFor(db, step_id, sensor);
  SqliteStatement statement(db, kInsert);
  ChecksummedInsert insert(statement);  // the columns in kCaptureChecksumColumns' order
  insert.Add(step_id).Add(capture.id).Add(std::string(CaptureKindToString(capture.kind)));
  insert.Add(capture.label).Add(capture.radius_m).Add(capture.rpm);
  if (capture.up_axis) {
    insert.Add(std::string(SensorAxisToString(*capture.up_axis)));
  } else {
    insert.AddNull();
  }
  insert.Add(capture.rejection_reason);
  // n counts every sample stored (the blob), including non-finite ones the stats skip.
  CaptureStats stats = capture.stats();
  stats.n = static_cast<long>(capture.samples.size());
  AddStats(insert, stats);
  insert.AddBlob(EncodeSamples(capture.samples)).Add(recorded_utc).Add(sensor);
  insert.BindChecksum();
  statement.Run();
}

CaptureRows ReadCaptureRows(SqliteDb& db, int sensor) { return ReadRows(db, "", sensor); }

void MarkCaptureRowSuperseded(SqliteDb& db, const std::string& step_id, const std::string& by_step_id) {
  // Every sensor's capture of the step (a fixture's pose is taken again for all of them).
  const CaptureRows existing = ReadRows(db, step_id, -1);
  if (existing.intact.empty())
    throw Error(fmt::format("session {}: step '{}' has no capture to supersede", db.path(), step_id));
  if (!existing.intact.front().superseded_by.empty())
    throw Error(fmt::format("session {}: the capture of step '{}' is already superseded by '{}'",
                            db.path(), step_id, existing.intact.front().superseded_by));
  SqliteStatement(db, "UPDATE captures SET superseded_by = ? WHERE step_id = ?")
      .Bind(1, by_step_id).Bind(2, step_id).Run();
}

}  // namespace accelcal::detail

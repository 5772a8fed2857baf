#include "accelcal/session/detail/capture_rows.h"

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/session/detail/sample_blob.h"

namespace accelcal::detail {
namespace {

constexpr const char* kInsert =
    "INSERT INTO captures (step_id, capture_id, kind, label, radius_m, rpm, up_axis, "
    "rejection_reason, n, mean_x_counts, mean_y_counts, mean_z_counts, comoment_xx_counts2, "
    "comoment_xy_counts2, comoment_xz_counts2, comoment_yy_counts2, comoment_yz_counts2, "
    "comoment_zz_counts2, t_first_s, "
    "t_last_s, mean_temp_c, samples, recorded_utc) "
    "VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)";

constexpr const char* kSelect =
    "SELECT step_id, capture_id, kind, label, radius_m, rpm, up_axis, rejection_reason, n, "
    "samples FROM captures ORDER BY seq";

bool StepHasCapture(SqliteDb& db, const std::string& step_id) {
  SqliteStatement query(db, "SELECT 1 FROM captures WHERE step_id = ?");
  query.Bind(1, step_id);
  return query.Step();
}

void BindStats(SqliteStatement& insert, const CaptureStats& stats) {
  insert.Bind(9, static_cast<std::int64_t>(stats.n));
  for (int i = 0; i < 3; ++i) insert.Bind(10 + i, stats.mean_counts(i));
  const Eigen::Matrix3d& c = stats.comoment_counts2;
  insert.Bind(13, c(0, 0)).Bind(14, c(0, 1)).Bind(15, c(0, 2));
  insert.Bind(16, c(1, 1)).Bind(17, c(1, 2)).Bind(18, c(2, 2));
  insert.Bind(19, stats.t_first_s).Bind(20, stats.t_last_s).Bind(21, stats.mean_temp_c);
}

Capture CaptureFromRow(const SqliteStatement& row, const std::string& path) {
  Capture c;
  c.id = static_cast<int>(row.ColumnInt(1));
  const std::string kind = row.ColumnText(2);
  const std::optional<CaptureKind> parsed = StringToCaptureKind(kind);
  if (!parsed) throw Error(fmt::format("session {}: capture with unknown kind '{}'", path, kind));
  c.kind = *parsed;
  c.label = row.ColumnText(3);
  c.radius_m = row.ColumnDouble(4);
  c.rpm = row.ColumnDouble(5);
  if (!row.ColumnIsNull(6)) c.up_axis = StringToSensorAxis(row.ColumnText(6));
  c.rejection_reason = row.ColumnText(7);
  c.samples = DecodeSamples(row.ColumnBlob(9));
  const std::int64_t n = row.ColumnInt(8);
  if (static_cast<std::int64_t>(c.samples.size()) != n)
    throw Error(fmt::format("session {}: step '{}' is damaged: {} samples stored, {} expected",
                            path, row.ColumnText(0), c.samples.size(), n));
  return c;
}

}  // namespace

void InsertCaptureRow(SqliteDb& db, const std::string& step_id, const Capture& capture,
                      const std::string& recorded_utc) {
  if (StepHasCapture(db, step_id))
    throw Error(fmt::format("session {}: step '{}' already has an accepted capture", db.path(),
                            step_id));
  SqliteStatement insert(db, kInsert);
  insert.Bind(1, step_id).Bind(2, capture.id).Bind(3, std::string(CaptureKindToString(capture.kind)));
  insert.Bind(4, capture.label).Bind(5, capture.radius_m).Bind(6, capture.rpm);
  if (capture.up_axis) {
    insert.Bind(7, std::string(SensorAxisToString(*capture.up_axis)));
  } else {
    insert.BindNull(7);
  }
  insert.Bind(8, capture.rejection_reason);
  // n counts every sample stored (the blob), including non-finite ones the stats skip.
  CaptureStats stats = capture.stats();
  stats.n = static_cast<long>(capture.samples.size());
  BindStats(insert, stats);
  insert.BindBlob(22, EncodeSamples(capture.samples)).Bind(23, recorded_utc);
  insert.Run();
}

std::vector<JournalCapture> ReadCaptureRows(SqliteDb& db) {
  std::vector<JournalCapture> out;
  SqliteStatement rows(db, kSelect);
  while (rows.Step()) out.push_back({rows.ColumnText(0), CaptureFromRow(rows, db.path())});
  return out;
}

}  // namespace accelcal::detail

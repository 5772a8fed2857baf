// LabStore's reading of the register: a device's history, what is due (lab_store.h).
#include <fmt/core.h>

#include "accelcal/lab/detail/pg_connection.h"
#include "accelcal/lab/detail/pg_sql.h"
#include "accelcal/lab/lab_store.h"

namespace accelcal {

using detail::IsoDate;
using detail::IsoUtc;
using detail::PgInt;
using detail::PgResult;
using detail::PgText;

namespace {

std::optional<long> DaysLeft(const PgResult& r, int row, int column) {
  if (r.IsNull(row, column)) return std::nullopt;
  return static_cast<long>(r.Int(row, column));
}

}  // namespace

LabHistory LabStore::History(const std::string& serial) const {
  const PgResult device =
      db_->Exec("SELECT coalesce(device_type, '') FROM accelcal.devices WHERE serial = $1", {PgText(serial)});
  if (device.rows() == 0) {
    const long long known = db_->Exec("SELECT count(*) FROM accelcal.devices").Int(0, 0);
    throw Error(
        fmt::format("no device {} in the lab's register ({} device(s) published; `accelcal lab due "
                    "--within 100000d` lists them)",
                    serial, known));
  }
  LabHistory h;
  h.serial = serial;
  h.device_type = device.Text(0, 0);
  const PgResult r =
      db_->Exec("SELECT certificate_number, session, session_uuid::text, bench, " + IsoUtc("date_utc") +
                    ", verdict, status, procedure, operator, coalesce(approved_by, ''), "
                    "coalesce(" +
                    IsoUtc("approved_utc") +
                    ", ''), coalesce(withdrawn_by, ''), "
                    "coalesce(" +
                    IsoUtc("withdrawn_utc") +
                    ", ''), coalesce(withdrawn_reason, '') "
                    "FROM accelcal.device_history WHERE serial = $1 ORDER BY date_utc, seq",
                {PgText(serial)});
  for (int i = 0; i < r.rows(); ++i) {
    LabHistoryEntry e;
    e.certificate_number = r.Text(i, 0);
    e.session = r.Text(i, 1);
    e.session_uuid = r.Text(i, 2);
    e.bench = r.Text(i, 3);
    e.date_utc = r.Text(i, 4);
    e.verdict = r.Text(i, 5);
    e.status = r.Text(i, 6);
    e.procedure = r.Text(i, 7);
    e.operator_name = r.Text(i, 8);
    e.approved_by = r.Text(i, 9);
    e.approved_utc = r.Text(i, 10);
    e.withdrawn_by = r.Text(i, 11);
    e.withdrawn_utc = r.Text(i, 12);
    e.withdrawn_reason = r.Text(i, 13);
    h.entries.push_back(std::move(e));
  }
  return h;
}

LabDueList LabStore::Due(int within_days) const {
  if (within_days < 0) throw Error(fmt::format("a window of {} days: it must be 0 or more", within_days));
  LabDueList due;
  due.within_days = within_days;
  due.today = db_->Exec("SELECT " + IsoDate("current_date")).Text(0, 0);
  // Devices: due `interval` after their last valid calibration, at once without one. Equipment:
  // when its latest certificate runs out, at once without one.
  const PgResult r = db_->Exec(
      "SELECT 'device', serial, coalesce(device_type, ''), '', coalesce(last_certificate_number, ''), "
      "coalesce(" +
          IsoDate("last_calibrated_utc") + ", ''), coalesce(" + IsoDate("due_utc") +
          ", ''), "
          "due_utc::date - current_date AS days_left "
          "FROM accelcal.device_due WHERE due_utc IS NULL OR due_utc::date <= current_date + $1::integer "
          "UNION ALL "
          "SELECT 'equipment', equipment_id, kind, name, coalesce(certificate_ref, ''), "
          "coalesce(" +
          IsoDate("calibrated_on") + ", ''), coalesce(" + IsoDate("valid_until") +
          ", ''), "
          "valid_until - current_date "
          "FROM accelcal.equipment_due WHERE valid_until IS NULL OR valid_until <= current_date + "
          "$1::integer "
          "ORDER BY days_left NULLS FIRST, 2",
      {PgInt(within_days)});
  for (int i = 0; i < r.rows(); ++i) {
    LabDueItem item;
    item.kind = r.Text(i, 0) == "device" ? LabDueItem::Kind::kDevice : LabDueItem::Kind::kEquipment;
    item.id = r.Text(i, 1);
    item.type = r.Text(i, 2);
    item.name = r.Text(i, 3);
    item.last = r.Text(i, 4);
    item.last_date = r.Text(i, 5);
    item.due_date = r.Text(i, 6);
    item.days_left = DaysLeft(r, i, 7);
    due.items.push_back(std::move(item));
  }
  return due;
}

}  // namespace accelcal

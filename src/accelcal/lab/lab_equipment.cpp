// LabStore's equipment register (lab_store.h).
#include <fmt/core.h>

#include "accelcal/lab/detail/pg_connection.h"
#include "accelcal/lab/detail/pg_sql.h"
#include "accelcal/lab/lab_store.h"

namespace accelcal {

using detail::IsoDate;
using detail::PgResult;
using detail::PgText;

namespace {

const std::string& StatusColumns() {
  static const std::string columns = "equipment_id, kind, name, coalesce(certificate_ref, ''), coalesce(" +
                                     IsoDate("calibrated_on") + ", ''), coalesce(" + IsoDate("valid_until") +
                                     ", ''), valid_until - current_date";
  return columns;
}

LabEquipmentStatus StatusAt(const PgResult& r, int i) {
  LabEquipmentStatus s;
  s.id = r.Text(i, 0);
  s.kind = r.Text(i, 1);
  s.name = r.Text(i, 2);
  s.certificate_ref = r.Text(i, 3);
  s.calibrated_on = r.Text(i, 4);
  s.valid_until = r.Text(i, 5);
  if (!r.IsNull(i, 6)) s.days_left = static_cast<long>(r.Int(i, 6));
  return s;
}

}  // namespace

std::vector<LabEquipmentStatus> LabStore::Equipment() const {
  const PgResult r =
      db_->Exec("SELECT " + StatusColumns() + " FROM accelcal.equipment_due ORDER BY equipment_id");
  std::vector<LabEquipmentStatus> items;
  for (int i = 0; i < r.rows(); ++i) items.push_back(StatusAt(r, i));
  return items;
}

std::vector<LabEquipmentStatus> LabStore::EquipmentStatus(const std::vector<std::string>& ids) const {
  std::vector<LabEquipmentStatus> items;
  for (const std::string& id : ids) {
    const PgResult r = db_->Exec(
        "SELECT " + StatusColumns() + " FROM accelcal.equipment_due WHERE equipment_id = $1", {PgText(id)});
    if (r.rows() == 1) {
      items.push_back(StatusAt(r, 0));
    } else {
      LabEquipmentStatus unknown;
      unknown.id = id;
      unknown.registered = false;
      items.push_back(std::move(unknown));
    }
  }
  return items;
}

void LabStore::RegisterEquipment(const LabEquipmentRegistration& item) {
  if (item.id.empty()) throw Error("an item of equipment needs its id");
  if (item.certificate_ref.empty() || item.calibrated_on.empty() || item.valid_until.empty())
    throw Error(
        fmt::format("equipment {}: its certificate, calibration date and validity are all needed", item.id));
  detail::PgTransaction transaction(*db_);
  db_->Exec(
      "INSERT INTO accelcal.equipment (equipment_id, kind, name) VALUES ($1, $2, $3) "
      "ON CONFLICT (equipment_id) DO UPDATE SET kind = EXCLUDED.kind, name = EXCLUDED.name",
      {PgText(item.id), PgText(item.kind), PgText(item.name)});
  const PgResult inserted = db_->Exec(
      "INSERT INTO accelcal.equipment_certificates (equipment_id, certificate_ref, calibrated_on, "
      "valid_until, issuer) VALUES ($1, $2, $3, $4, $5) ON CONFLICT (equipment_id, certificate_ref) DO "
      "NOTHING",
      {PgText(item.id), PgText(item.certificate_ref), PgText(item.calibrated_on), PgText(item.valid_until),
       PgText(item.issuer)});
  if (inserted.Affected() == 0) {
    // Registered before: the same again is fine, other dates are a mistake to say.
    const PgResult held = db_->Exec(
        "SELECT " + IsoDate("calibrated_on") + ", " + IsoDate("valid_until") +
            " FROM accelcal.equipment_certificates WHERE equipment_id = $1 AND certificate_ref = $2",
        {PgText(item.id), PgText(item.certificate_ref)});
    if (held.Text(0, 0) != item.calibrated_on || held.Text(0, 1) != item.valid_until)
      throw Error(
          fmt::format("equipment {}: certificate {} is registered already, calibrated {} and valid "
                      "until {}; a new certificate has a new reference",
                      item.id, item.certificate_ref, held.Text(0, 0), held.Text(0, 1)));
  }
  transaction.Commit();
}

}  // namespace accelcal

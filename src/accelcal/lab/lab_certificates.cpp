// LabStore's lab-manager operations: certificate status, device types (lab_store.h).
#include <fmt/core.h>

#include "accelcal/lab/detail/pg_connection.h"
#include "accelcal/lab/lab_store.h"

namespace accelcal {

using detail::PgInt;
using detail::PgResult;
using detail::PgText;

void LabStore::SetCertificateStatus(const std::string& certificate_number, LabCertificateStatus status,
                                    const std::string& reason) {
  PgResult r = status == LabCertificateStatus::kWithdrawn
                   ? db_->Exec(
                         "UPDATE accelcal.certificates SET status = 'withdrawn', withdrawn_reason = $2 "
                         "WHERE certificate_number = $1",
                         {PgText(certificate_number), PgText(reason)})
                   : db_->Exec("UPDATE accelcal.certificates SET status = $2 WHERE certificate_number = $1",
                               {PgText(certificate_number), PgText(LabCertificateStatusText(status))});
  if (r.Affected() == 0)
    throw Error(fmt::format("no certificate {} in the lab's register", certificate_number));
}

void LabStore::SetDeviceTypeInterval(const std::string& device_type, int interval_days) {
  if (interval_days <= 0)
    throw Error(fmt::format("a recalibration interval of {} days: it must be 1 or more", interval_days));
  db_->Exec(
      "INSERT INTO accelcal.device_types (device_type, recal_interval_days) VALUES ($1, $2) "
      "ON CONFLICT (device_type) DO UPDATE SET recal_interval_days = EXCLUDED.recal_interval_days",
      {PgText(device_type), PgInt(interval_days)});
}

void LabStore::SetDeviceType(const std::string& serial, const std::string& device_type) {
  PgResult r = [&] {
    try {
      return db_->Exec("UPDATE accelcal.devices SET device_type = $2 WHERE serial = $1",
                       {PgText(serial), PgText(device_type)});
    } catch (const LabError& e) {
      if (e.sqlstate() != "23503") throw;  // foreign_key_violation: an unknown type
      throw Error(
          fmt::format("no device type {} in the lab: set its interval first (accelcal lab "
                      "device-type {} --interval 365d)",
                      device_type, device_type));
    }
  }();
  if (r.Affected() == 0) throw Error(fmt::format("no device {} in the lab's register", serial));
}

}  // namespace accelcal

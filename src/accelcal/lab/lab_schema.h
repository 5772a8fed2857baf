// The lab store's schema in PostgreSQL, created and migrated by accelcal itself (accelcal lab
// migrate, run by the lab's administrator: the role that owns the database), versioned: each
// version is one migration, applied in its own transaction and recorded in
// accelcal.schema_migrations (version, description, older_clients_ok, applied_utc, applied_by).
// Migrations are only ever appended: what version N creates never changes once released, so a
// store at any earlier version reaches the latest by the same steps as one created today
// (tests/lab/lab_schema_test.cpp migrates from each).
//
//   1  the register: schema accelcal; roles accelcal_bench and accelcal_manager (created when
//      missing: cluster-wide, NOLOGIN groups a lab's login roles join); lab_settings (the lab's
//      id, the certificate numbers' prefix); devices; sessions -> session_sensors ->
//      calibrations -> certificates -> certificate_documents (the bytes as rendered);
//      session_equipment; equipment and equipment_certificates; the certificate sequence;
//      grants, row-level security and the rules below.
//   2  recalibration due: device_types (interval in days), devices.device_type,
//      lab_settings.default_recal_interval_days (365), the views device_due and equipment_due.
//   3  the history view device_history (one row per certificate, withdrawn ones included).
//
// The rules the database enforces (docs/lab.md, "Roles"):
//  - a bench (a member of accelcal_bench) reads everything and inserts only its own sessions and
//    what hangs from them (row-level security: sessions.bench = current_user); it updates and
//    deletes nothing;
//  - a certificate's number is drawn from the lab's sequence by
//    accelcal.draw_certificate_number() and must be the one the inserting connection drew last
//    (a trigger): no number is chosen by a client, none is used twice;
//  - only a lab manager (a member of accelcal_manager) changes a certificate's status: issued ->
//    approved -> withdrawn (issued -> withdrawn too; withdrawn is final, with its reason), the
//    trigger stamping who and when; nobody deletes a certificate, its documents or a
//    calibration (no grant, and a trigger that refuses even the owner).
// A refusal comes back as SQLSTATE 42501 (lab_error.h).
#pragma once

#include <string_view>
#include <vector>

namespace accelcal {

inline constexpr int kLabSchemaVersion = 3;

struct LabMigration {
  int version = 0;
  std::string_view description;
  // True when an accelcal that knows only the versions before this one still works correctly
  // on a store with it (it only adds): such a bench goes on until it is updated.
  bool older_clients_ok = true;
  std::string_view sql;
};

// Every migration, in order: LabMigrations()[i].version == i + 1.
const std::vector<LabMigration>& LabMigrations();

}  // namespace accelcal

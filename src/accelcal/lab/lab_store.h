// The lab's store: one PostgreSQL database that every bench of a lab publishes its finished
// calibrations to (docs/lab.md). The bench stays self-contained (its sessions are SQLite files,
// session/session_store.h); publishing copies a finished session here, once.
//
// Connection: libpq's own settings only (detail/pg_connection.h): PG* variables, the service
// file, ~/.pgpass. The schema is accelcal's (lab_schema.h), created and migrated by Migrate();
// the roles and what each may do are enforced by the database itself.
//
// Publishing is idempotent and safe to retry: a session is keyed by its UUID, and all of it
// (session, sensors, calibrations, certificates and their documents, equipment) is written in
// one transaction, so a publisher killed or cut off at any instant leaves nothing partial, and a
// session published again, or concurrently from two processes, is one row with its first
// certificate numbers.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accelcal/lab/lab_error.h"
#include "accelcal/lab/lab_publication.h"
#include "accelcal/lab/lab_schema.h"
#include "accelcal/report/lab_register.h"

namespace accelcal {

namespace detail {
class PgConnection;
}

// True when this bench is pointed at a lab's store: one of libpq's variables that name a server
// or a service (PGSERVICE, PGHOST, PGHOSTADDR, PGDATABASE) is set. The wizard checks it before it
// offers to publish or checks the equipment, so a bench without a lab never waits on one;
// `accelcal lab ...` commands connect regardless (libpq's defaults: the local server).
bool LabConfigured();

// The longest the wizard waits for the lab's server, s (libpq's connect_timeout; its minimum is 2).
inline constexpr int kLabQuickConnectTimeoutS = 3;

enum class LabCertificateStatus { kIssued, kApproved, kWithdrawn };
std::string LabCertificateStatusText(LabCertificateStatus status);  // "issued", ...

// Registering an item of equipment, or a new certificate of an item already registered.
struct LabEquipmentRegistration {
  std::string id;
  std::string kind;  // "ruler", "turntable", "level", "prism", ...
  std::string name;
  std::string certificate_ref;  // its calibration certificate's reference
  std::string calibrated_on;    // "2026-01-10"
  std::string valid_until;      // "2027-01-10"
  std::string issuer;           // who calibrated it (optional)
};

struct LabSchemaState {
  int version = 0;      // 0: no accelcal schema yet
  bool usable = false;  // this accelcal may read and publish with it
  std::string problem;  // why not, and what to do
};

class LabStore {
 public:
  // Connects. Throws LabError: unreachable (unreachable()), or, unless `administer` (migrate,
  // status), a schema this accelcal cannot use (none yet, older, or newer in a way that breaks it).
  static std::unique_ptr<LabStore> Connect(bool administer = false);
  // Connect() for a technician who is waiting (the wizard's welcome and end): at most
  // kLabQuickConnectTimeoutS s for the server, whatever libpq's settings say (PGCONNECT_TIMEOUT
  // only when shorter), per address of its host; a server that does not answer in time is a
  // LabError unreachable().
  static std::unique_ptr<LabStore> ConnectQuickly();
  ~LabStore();
  LabStore(const LabStore&) = delete;
  LabStore& operator=(const LabStore&) = delete;

  // "lab 7c9e...e1 (database lab on db.lab.example:5432 as bench_3)": which store, for the
  // bench's record; it starts with "lab " + LabId().
  std::string Identity() const;
  // The register's own id (a UUID made when it was created), the same from every bench.
  const std::string& LabId() const { return lab_id_; }
  const std::string& Role() const { return role_; }  // the role connected as (current_user)
  // The roles it is a member of among accelcal_bench and accelcal_manager.
  std::vector<std::string> LabRoles() const;
  LabSchemaState SchemaState() const;

  // Applies the migrations above the store's version up to `target` (lab_schema.h), each in its
  // own transaction under an advisory lock (two administrators at once apply each once).
  // Returns the versions applied. Needs the rights of the database's owner (and CREATEROLE the
  // first time, to create the two group roles when they do not exist).
  std::vector<int> Migrate(int target = kLabSchemaVersion);

  // Publishes `publication` (see above); `render` makes each sensor's certificate once its number
  // is drawn. Throws LabError (refused, unreachable, lost) with nothing written, or Error when
  // the store already holds the session with another calibration (changed after it was
  // published: the lab keeps what it certified).
  LabPublishResult Publish(const LabPublication& publication, const LabCertificateRenderer& render);

  // Every certificate of the device `serial`, withdrawn ones included. Throws Error when the lab
  // has no device of that serial.
  LabHistory History(const std::string& serial) const;
  // Devices and equipment due within `within_days` days from today (overdue ones included).
  LabDueList Due(int within_days) const;
  // The lab's equipment and each item's latest certificate, by id.
  std::vector<LabEquipmentStatus> Equipment() const;
  // The items `ids` (an id the lab does not know comes back with registered = false).
  std::vector<LabEquipmentStatus> EquipmentStatus(const std::vector<std::string>& ids) const;
  // A lab manager's: registers an item (or its name and kind again) with a new certificate.
  void RegisterEquipment(const LabEquipmentRegistration& item);

  // A lab manager's: approves (signs) or withdraws a certificate (the reason required to
  // withdraw). Throws LabError refused() for any other role.
  void SetCertificateStatus(const std::string& certificate_number, LabCertificateStatus status,
                            const std::string& reason = "");
  // The stored documents of a certificate (as rendered when it was issued).
  std::vector<LabDocument> CertificateDocuments(const std::string& certificate_number) const;
  // A lab manager's: a device type's recalibration interval, and a device's type.
  void SetDeviceTypeInterval(const std::string& device_type, int interval_days);
  void SetDeviceType(const std::string& serial, const std::string& device_type);

 private:
  explicit LabStore(std::unique_ptr<detail::PgConnection> db);
  static std::unique_ptr<LabStore> Connect(bool administer, int connect_timeout_s);
  void ReadLabId();  // empty while the store has no register (or this role may not read it)
  std::unique_ptr<detail::PgConnection> db_;
  std::string role_;
  std::string lab_id_;
};

}  // namespace accelcal

#include "accelcal/lab/lab_store.h"

#include <cstdlib>

#include <fmt/core.h>

#include "accelcal/lab/detail/pg_connection.h"

namespace accelcal {

using detail::PgInt;
using detail::PgText;

namespace {

// The key of the advisory lock migrations take (the bytes of "accelcal"): two administrators
// migrating at once apply each version once.
constexpr long long kMigrationLockKey = 0x616363656c63616cLL;

// (A query naming a table that does not exist fails when it is parsed: so two queries.)
bool TableReadable(detail::PgConnection& db, const std::string& table) {
  const detail::PgResult r = db.Exec(
      "SELECT CASE WHEN to_regclass($1) IS NULL THEN false ELSE has_table_privilege($1, 'SELECT') END",
      {PgText(table)});
  return r.Text(0, 0) == "t";
}

int CurrentVersion(detail::PgConnection& db) {
  if (!TableReadable(db, "accelcal.schema_migrations")) return 0;
  return static_cast<int>(
      db.Exec("SELECT coalesce(max(version), 0) FROM accelcal.schema_migrations").Int(0, 0));
}

}  // namespace

bool LabConfigured() {
  for (const char* name : {"PGSERVICE", "PGHOST", "PGHOSTADDR", "PGDATABASE"})
    if (const char* value = std::getenv(name); value != nullptr && *value != '\0') return true;
  return false;
}

std::string LabCertificateStatusText(LabCertificateStatus status) {
  switch (status) {
    case LabCertificateStatus::kApproved:
      return "approved";
    case LabCertificateStatus::kWithdrawn:
      return "withdrawn";
    case LabCertificateStatus::kIssued:
      break;
  }
  return "issued";
}

LabStore::LabStore(std::unique_ptr<detail::PgConnection> db) : db_(std::move(db)) {
  role_ = db_->Exec("SELECT current_user").Text(0, 0);
}

LabStore::~LabStore() = default;

std::unique_ptr<LabStore> LabStore::Connect(bool administer) { return Connect(administer, 0); }

std::unique_ptr<LabStore> LabStore::ConnectQuickly() { return Connect(false, kLabQuickConnectTimeoutS); }

std::unique_ptr<LabStore> LabStore::Connect(bool administer, int connect_timeout_s) {
  std::unique_ptr<LabStore> store(new LabStore(std::make_unique<detail::PgConnection>(connect_timeout_s)));
  if (!administer) {
    const LabSchemaState state = store->SchemaState();
    if (!state.usable) throw LabError(state.problem, "");
  }
  store->ReadLabId();
  return store;
}

void LabStore::ReadLabId() {
  lab_id_.clear();
  if (TableReadable(*db_, "accelcal.lab_settings"))
    lab_id_ = db_->Exec("SELECT lab_id::text FROM accelcal.lab_settings WHERE id = 1").Text(0, 0);
}

std::string LabStore::Identity() const {
  return fmt::format("lab {} ({})", lab_id_.empty() ? "?" : lab_id_, db_->Where());
}

std::vector<std::string> LabStore::LabRoles() const {
  const detail::PgResult r = db_->Exec(
      "SELECT rolname FROM pg_roles WHERE rolname IN ('accelcal_bench', 'accelcal_manager') "
      "AND pg_has_role(current_user, oid, 'MEMBER') ORDER BY rolname");
  std::vector<std::string> roles;
  for (int i = 0; i < r.rows(); ++i) roles.push_back(r.Text(i, 0));
  return roles;
}

LabSchemaState LabStore::SchemaState() const {
  LabSchemaState s;
  const detail::PgResult access = db_->Exec(
      "SELECT EXISTS (SELECT 1 FROM pg_namespace WHERE nspname = 'accelcal'), "
      "CASE WHEN EXISTS (SELECT 1 FROM pg_namespace WHERE nspname = 'accelcal') "
      "THEN has_schema_privilege('accelcal', 'USAGE') ELSE false END");
  const bool exists = access.Text(0, 0) == "t";
  if (!exists) {
    s.problem = fmt::format(
        "the lab store ({}) has no accelcal register yet: its administrator "
        "creates it with `accelcal lab migrate`",
        db_->Where());
    return s;
  }
  if (access.Text(0, 1) != "t") {
    s.problem = fmt::format(
        "role {} may not use the lab's register ({}): the administrator makes it "
        "a bench (GRANT accelcal_bench TO {}) or a lab manager (accelcal_manager)",
        role_, db_->Where(), role_);
    return s;
  }
  s.version = CurrentVersion(*db_);
  if (s.version < kLabSchemaVersion) {
    s.problem = fmt::format(
        "the lab store ({}) has register version {}, older than this accelcal's "
        "({}): its administrator runs `accelcal lab migrate` with this accelcal",
        db_->Where(), s.version, kLabSchemaVersion);
    return s;
  }
  if (s.version > kLabSchemaVersion) {
    const detail::PgResult breaking = db_->Exec(
        "SELECT string_agg(version::text, ', ' ORDER BY version) FROM accelcal.schema_migrations "
        "WHERE version > $1 AND NOT older_clients_ok",
        {PgInt(kLabSchemaVersion)});
    if (!breaking.IsNull(0, 0)) {
      s.problem = fmt::format(
          "the lab store ({}) has register version {}, whose version(s) {} this "
          "accelcal ({}) cannot work with: update accelcal on this bench",
          db_->Where(), s.version, breaking.Text(0, 0), kLabSchemaVersion);
      return s;
    }
  }
  s.usable = true;
  return s;
}

std::vector<int> LabStore::Migrate(int target) {
  if (target < 1 || target > kLabSchemaVersion)
    throw Error(fmt::format("register version {} is not one this accelcal knows (1 to {})", target,
                            kLabSchemaVersion));
  // A lock held by the connection across the migrations, taken before their transactions begin:
  // a transaction that began before another administrator's commit could still see the register
  // as it was (PostgreSQL's catalog caches are refreshed when a transaction starts).
  db_->Exec("SELECT pg_advisory_lock($1)", {PgInt(kMigrationLockKey)});
  std::vector<int> applied;
  try {
    for (const LabMigration& m : LabMigrations()) {
      if (m.version > target) break;
      detail::PgTransaction transaction(*db_);
      if (CurrentVersion(*db_) >= m.version) continue;  // applied already (rolled back: nothing written)
      db_->ExecScript(std::string(m.sql));
      db_->Exec(
          "INSERT INTO accelcal.schema_migrations (version, description, older_clients_ok) "
          "VALUES ($1, $2, $3)",
          {PgInt(m.version), PgText(std::string(m.description)),
           PgText(m.older_clients_ok ? "true" : "false")});
      transaction.Commit();
      applied.push_back(m.version);
    }
  } catch (const LabError&) {
    // (A lost connection has released the lock already.)
    try {
      db_->Exec("SELECT pg_advisory_unlock($1)", {PgInt(kMigrationLockKey)});
    } catch (const LabError&) {
    }
    throw;
  }
  db_->Exec("SELECT pg_advisory_unlock($1)", {PgInt(kMigrationLockKey)});
  ReadLabId();
  return applied;
}

}  // namespace accelcal

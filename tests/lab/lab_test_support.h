// The lab store's tests run against a real PostgreSQL that tests/lab/with_server.sh starts
// (pg_server.sh): PGHOST, PGPORT set, the role lab_admin owning the database `lab`. Each test
// gets a fresh database of its own, made by lab_admin, and connects to it by PGDATABASE and
// PGUSER, as a bench would: libpq's settings, nothing else.
#pragma once

#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <gtest/gtest.h>

#include "accelcal/lab/detail/pg_connection.h"
#include "accelcal/base/uuid.h"
#include "accelcal/lab/lab_store.h"

namespace accelcal::testing {

// Login roles of the tests (cluster-wide: created once, kept): benches, a lab manager, and a
// role that is neither.
inline const std::vector<std::string>& BenchRoles() {
  static const std::vector<std::string> roles = {"bench_1", "bench_2", "bench_3", "bench_4",
                                                 "bench_5", "bench_6", "bench_7", "bench_8"};
  return roles;
}
inline constexpr const char* kManager = "lab_manager_1";
inline constexpr const char* kOutsider = "visitor_1";
inline constexpr const char* kAdmin = "lab_admin";

// The environment variable `name` set to `value` for the life of this object.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_.empty())
      ::unsetenv(name_);
    else
      ::setenv(name_, old_.c_str(), 1);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::string old_;
};

// A fixture whose StartMigrated() is true starts from a register at the latest version (a copy of
// a template database migrated once per run: faster than migrating each test's); else from an
// empty database.
class LabDatabaseTest : public ::testing::Test {
 protected:
  virtual bool StartMigrated() const { return false; }

  void SetUp() override {
    ASSERT_NE(std::getenv("PGHOST"), nullptr) << "run by tests/lab/with_server.sh, which starts the server";
    database_ = fmt::format("t_{}", std::random_device{}() % 100000000);
    {
      ScopedEnv db("PGDATABASE", "lab");
      ScopedEnv user("PGUSER", kAdmin);
      detail::PgConnection admin;
      EnsureRoles(admin);
      if (StartMigrated()) MakeMigratedTemplate(admin);
      admin.ExecScript("CREATE DATABASE " + database_ + (StartMigrated() ? " TEMPLATE " + std::string(kTemplate) : ""));
    }
    ::setenv("PGDATABASE", database_.c_str(), 1);
    ::setenv("PGUSER", kAdmin, 1);
  }

  void TearDown() override {
    ::setenv("PGDATABASE", "lab", 1);
    ::setenv("PGUSER", kAdmin, 1);
    // As the superuser: FORCE ends the backends of connections just closed that are still
    // going away, which only a superuser may do to other roles' backends.
    ScopedEnv user("PGUSER", "postgres");
    detail::PgConnection superuser;
    superuser.ExecScript("DROP DATABASE IF EXISTS " + database_ + " WITH (FORCE)");
  }

  // The register created (as the administrator) at `version` in the database of PGDATABASE, the
  // tests' login roles joined to its groups (as a lab's administrator does: GRANT accelcal_bench
  // TO bench_1, ...).
  static void Migrate(int version = kLabSchemaVersion) {
    ScopedEnv user("PGUSER", kAdmin);
    LabStore::Connect(true)->Migrate(version);
    detail::PgConnection admin;
    for (const std::string& r : BenchRoles()) admin.ExecScript("GRANT accelcal_bench TO " + r);
    admin.ExecScript(std::string("GRANT accelcal_manager TO ") + kManager);
  }

  // A store connection as `role` (administer: no schema check, for older versions).
  static std::unique_ptr<LabStore> As(const std::string& role, bool administer = false) {
    ScopedEnv user("PGUSER", role);
    return LabStore::Connect(administer);
  }
  // A raw connection as `role`, for what accelcal itself never sends (a DELETE, a forged row).
  static std::unique_ptr<detail::PgConnection> RawAs(const std::string& role) {
    ScopedEnv user("PGUSER", role);
    return std::make_unique<detail::PgConnection>();
  }

  const std::string& database() const { return database_; }

 private:
  static constexpr const char* kTemplate = "t_migrated_template";

  // The template, made once per run (its connections closed: a template is copied only alone).
  static void MakeMigratedTemplate(detail::PgConnection& admin) {
    static bool made = false;
    if (made) return;
    admin.ExecScript(std::string("DROP DATABASE IF EXISTS ") + kTemplate);
    admin.ExecScript(std::string("CREATE DATABASE ") + kTemplate);
    ScopedEnv db("PGDATABASE", kTemplate);
    Migrate();
    made = true;
  }

  // Creates the login roles once per cluster; joins them to the lab's groups once those exist.
  static void EnsureRoles(detail::PgConnection& admin) {
    std::vector<std::string> roles = BenchRoles();
    roles.push_back(kManager);
    roles.push_back(kOutsider);
    for (const std::string& r : roles)
      admin.ExecScript(
          fmt::format("DO $$ BEGIN IF NOT EXISTS (SELECT FROM pg_roles WHERE rolname = '{0}') "
                      "THEN CREATE ROLE {0} LOGIN; END IF; END $$",
                      r));
  }

  std::string database_;
};

// A publication of one sensor, as a bench would send it (the calibration's text stands for the
// calibration file's: the store keeps it as it is).
inline LabPublication MakePublication(const std::string& uuid, const std::string& serial,
                                      const std::string& date_utc = "2026-01-15T10:00:00.000Z",
                                      const std::string& verdict = "PASS") {
  LabPublication p;
  p.session_uuid = uuid;
  p.session_name = "s-" + uuid.substr(0, 8);
  p.procedure = "Full calibration";
  p.source = "sim";
  p.operator_name = "op";
  p.place = "bench room";
  p.gravity = "9.80665 +- 0.02309 m/s^2 (standard gravity, not the local value)";
  p.gravity_mps2 = 9.80665;
  p.gravity_sigma_mps2 = 0.02309;
  p.created_utc = date_utc;
  p.finished_utc = date_utc;
  p.accelcal_version = "test";
  p.sensors.push_back({0, serial, "{\"calibration\": \"" + uuid + "\"}", verdict, date_utc});
  p.equipment.push_back({"turntable", "TT-01", "turntable", "0.2 %", "the lab's tachometer"});
  return p;
}

// A renderer that writes the number into both documents (as the report does).
inline LabCertificateRenderer NumberedRenderer() {
  return [](const LabSensorCalibration& s, const std::string& number) {
    return std::vector<LabDocument>{
        {"text/html", fmt::format("<html><p>Certificate No. {} of {}</p></html>", number, s.device_serial)},
        {"text/plain", fmt::format("Certificate No. {}\n", number)}};
  };
}

}  // namespace accelcal::testing

#include "accelcal/lab/lab_schema.h"

#include <string>

#include <fmt/core.h>

namespace accelcal {
namespace {

// Version 1: the register. Functions that must see what the calling role may not (the sequence)
// are SECURITY DEFINER with a fixed search_path (PostgreSQL's manual, "Writing SECURITY DEFINER
// Functions Safely"); the rules' triggers stamp session_user, the role that logged in.
constexpr std::string_view kVersion1Register = R"sql(
DO $roles$
BEGIN
  IF NOT EXISTS (SELECT FROM pg_roles WHERE rolname = 'accelcal_bench') THEN
    CREATE ROLE accelcal_bench NOLOGIN;
  END IF;
  IF NOT EXISTS (SELECT FROM pg_roles WHERE rolname = 'accelcal_manager') THEN
    CREATE ROLE accelcal_manager NOLOGIN;
  END IF;
END
$roles$;

CREATE SCHEMA accelcal;
REVOKE ALL ON SCHEMA accelcal FROM PUBLIC;
GRANT USAGE ON SCHEMA accelcal TO accelcal_bench, accelcal_manager;

CREATE TABLE accelcal.schema_migrations (
  version integer PRIMARY KEY CHECK (version > 0),
  description text NOT NULL,
  older_clients_ok boolean NOT NULL,
  applied_utc timestamptz NOT NULL DEFAULT now(),
  applied_by text NOT NULL DEFAULT session_user);

CREATE TABLE accelcal.lab_settings (
  id integer PRIMARY KEY CHECK (id = 1),
  lab_id uuid NOT NULL DEFAULT gen_random_uuid(),
  -- Certificate numbers are PREFIX + six digits or more; the HTML puts them in CSS strings.
  certificate_prefix text NOT NULL DEFAULT 'LAB-' CHECK (certificate_prefix ~ '^[A-Za-z0-9._-]{0,16}$'));
INSERT INTO accelcal.lab_settings (id) VALUES (1);

CREATE TABLE accelcal.devices (
  serial text PRIMARY KEY CHECK (serial <> ''),
  first_seen_utc timestamptz NOT NULL DEFAULT now(),
  first_bench text NOT NULL DEFAULT current_user);

CREATE TABLE accelcal.sessions (
  session_uuid uuid PRIMARY KEY,
  bench text NOT NULL DEFAULT current_user,
  name text NOT NULL,
  procedure text NOT NULL,
  source text NOT NULL,
  operator text NOT NULL,
  place text NOT NULL,
  gravity text NOT NULL,
  gravity_mps2 double precision,
  gravity_sigma_mps2 double precision,
  created_utc timestamptz NOT NULL,
  finished_utc timestamptz NOT NULL,
  accelcal_version text NOT NULL,
  published_utc timestamptz NOT NULL DEFAULT now());

CREATE TABLE accelcal.session_sensors (
  session_uuid uuid NOT NULL REFERENCES accelcal.sessions,
  sensor_index integer NOT NULL CHECK (sensor_index >= 0),
  device_serial text NOT NULL REFERENCES accelcal.devices,
  PRIMARY KEY (session_uuid, sensor_index));
CREATE INDEX session_sensors_by_device ON accelcal.session_sensors (device_serial);

CREATE TABLE accelcal.calibrations (
  session_uuid uuid NOT NULL,
  sensor_index integer NOT NULL,
  calibration_json text NOT NULL,
  calibration_sha256 text NOT NULL,
  verdict text NOT NULL,
  date_utc timestamptz NOT NULL,
  PRIMARY KEY (session_uuid, sensor_index),
  FOREIGN KEY (session_uuid, sensor_index) REFERENCES accelcal.session_sensors);

CREATE SEQUENCE accelcal.certificate_seq AS bigint;

CREATE TABLE accelcal.certificates (
  certificate_number text PRIMARY KEY,
  seq bigint NOT NULL UNIQUE,
  session_uuid uuid NOT NULL,
  sensor_index integer NOT NULL,
  issued_utc timestamptz NOT NULL DEFAULT now(),
  issued_by text NOT NULL DEFAULT current_user,
  status text NOT NULL DEFAULT 'issued' CHECK (status IN ('issued', 'approved', 'withdrawn')),
  approved_by text,
  approved_utc timestamptz,
  withdrawn_by text,
  withdrawn_utc timestamptz,
  withdrawn_reason text,
  UNIQUE (session_uuid, sensor_index),
  FOREIGN KEY (session_uuid, sensor_index) REFERENCES accelcal.calibrations);

CREATE TABLE accelcal.certificate_documents (
  certificate_number text NOT NULL REFERENCES accelcal.certificates,
  media_type text NOT NULL CHECK (media_type IN ('text/html', 'text/plain', 'application/pdf')),
  content bytea NOT NULL,
  sha256 text NOT NULL,
  PRIMARY KEY (certificate_number, media_type));

CREATE TABLE accelcal.session_equipment (
  session_uuid uuid NOT NULL REFERENCES accelcal.sessions,
  role text NOT NULL,
  equipment_id text NOT NULL,
  name text NOT NULL,
  uncertainty text NOT NULL,
  traceability text NOT NULL,
  PRIMARY KEY (session_uuid, role));

CREATE TABLE accelcal.equipment (
  equipment_id text PRIMARY KEY CHECK (equipment_id <> ''),
  kind text NOT NULL,
  name text NOT NULL,
  registered_utc timestamptz NOT NULL DEFAULT now(),
  registered_by text NOT NULL DEFAULT current_user);

CREATE TABLE accelcal.equipment_certificates (
  equipment_id text NOT NULL REFERENCES accelcal.equipment,
  certificate_ref text NOT NULL CHECK (certificate_ref <> ''),
  calibrated_on date NOT NULL,
  valid_until date NOT NULL,
  issuer text NOT NULL DEFAULT '',
  registered_utc timestamptz NOT NULL DEFAULT now(),
  registered_by text NOT NULL DEFAULT current_user,
  PRIMARY KEY (equipment_id, certificate_ref),
  CHECK (valid_until > calibrated_on));

-- Certificate numbers: drawn here, never chosen by a client.
CREATE FUNCTION accelcal.certificate_number_of(seq bigint) RETURNS text
  LANGUAGE sql STABLE SECURITY DEFINER SET search_path = pg_catalog, pg_temp
  AS $$ SELECT certificate_prefix || lpad(seq::text, 6, '0') FROM accelcal.lab_settings WHERE id = 1 $$;
CREATE FUNCTION accelcal.draw_certificate_number(OUT seq bigint, OUT certificate_number text)
  LANGUAGE plpgsql VOLATILE SECURITY DEFINER SET search_path = pg_catalog, pg_temp AS $$
BEGIN
  seq := nextval('accelcal.certificate_seq');
  certificate_number := accelcal.certificate_number_of(seq);
END $$;
REVOKE ALL ON FUNCTION accelcal.certificate_number_of(bigint) FROM PUBLIC;
REVOKE ALL ON FUNCTION accelcal.draw_certificate_number() FROM PUBLIC;
GRANT EXECUTE ON FUNCTION accelcal.draw_certificate_number() TO accelcal_bench;

CREATE FUNCTION accelcal.check_certificate_issue() RETURNS trigger
  LANGUAGE plpgsql SECURITY DEFINER SET search_path = pg_catalog, pg_temp AS $$
DECLARE
  drawn bigint;
BEGIN
  BEGIN
    drawn := currval('accelcal.certificate_seq');
  EXCEPTION WHEN object_not_in_prerequisite_state THEN
    drawn := NULL;  -- this connection drew no number
  END;
  IF drawn IS DISTINCT FROM NEW.seq OR NEW.certificate_number <> accelcal.certificate_number_of(NEW.seq) THEN
    RAISE EXCEPTION 'certificate number % is not the one this connection just drew from the lab''s sequence',
      NEW.certificate_number USING ERRCODE = 'insufficient_privilege';
  END IF;
  RETURN NEW;
END $$;
CREATE TRIGGER certificate_number_drawn BEFORE INSERT ON accelcal.certificates
  FOR EACH ROW EXECUTE FUNCTION accelcal.check_certificate_issue();

CREATE FUNCTION accelcal.check_certificate_status() RETURNS trigger LANGUAGE plpgsql AS $$
BEGIN
  IF (NEW.certificate_number, NEW.seq, NEW.session_uuid, NEW.sensor_index, NEW.issued_utc, NEW.issued_by)
     IS DISTINCT FROM
     (OLD.certificate_number, OLD.seq, OLD.session_uuid, OLD.sensor_index, OLD.issued_utc, OLD.issued_by) THEN
    RAISE EXCEPTION 'certificate %: only its status changes', OLD.certificate_number
      USING ERRCODE = 'insufficient_privilege';
  END IF;
  IF OLD.status = 'withdrawn' THEN
    RAISE EXCEPTION 'certificate % was withdrawn on % by %: a withdrawn certificate stays withdrawn',
      OLD.certificate_number, to_char(OLD.withdrawn_utc, 'YYYY-MM-DD'), OLD.withdrawn_by
      USING ERRCODE = 'check_violation';
  END IF;
  IF NEW.status = 'approved' AND OLD.status = 'issued' THEN
    NEW.approved_by := session_user;
    NEW.approved_utc := now();
    NEW.withdrawn_reason := NULL;
  ELSIF NEW.status = 'withdrawn' THEN
    IF coalesce(btrim(NEW.withdrawn_reason), '') = '' THEN
      RAISE EXCEPTION 'certificate %: a withdrawal states its reason', OLD.certificate_number
        USING ERRCODE = 'check_violation';
    END IF;
    NEW.withdrawn_by := session_user;
    NEW.withdrawn_utc := now();
  ELSE
    RAISE EXCEPTION 'certificate % is %: it cannot become %', OLD.certificate_number, OLD.status, NEW.status
      USING ERRCODE = 'check_violation';
  END IF;
  RETURN NEW;
END $$;
CREATE TRIGGER certificate_status_rules BEFORE UPDATE ON accelcal.certificates
  FOR EACH ROW EXECUTE FUNCTION accelcal.check_certificate_status();

-- What is published stays: no grant deletes it, and these refuse even the owner.
CREATE FUNCTION accelcal.refuse_change() RETURNS trigger LANGUAGE plpgsql AS $$
BEGIN
  RAISE EXCEPTION '% of accelcal.%: published records are never changed or deleted '
    '(a certificate is withdrawn, never removed)',
    lower(TG_OP), TG_TABLE_NAME USING ERRCODE = 'insufficient_privilege';
END $$;
CREATE TRIGGER certificates_stay BEFORE DELETE ON accelcal.certificates
  FOR EACH ROW EXECUTE FUNCTION accelcal.refuse_change();
CREATE TRIGGER certificates_stay_whole BEFORE TRUNCATE ON accelcal.certificates
  FOR EACH STATEMENT EXECUTE FUNCTION accelcal.refuse_change();
CREATE TRIGGER documents_stay BEFORE UPDATE OR DELETE ON accelcal.certificate_documents
  FOR EACH ROW EXECUTE FUNCTION accelcal.refuse_change();
CREATE TRIGGER documents_stay_whole BEFORE TRUNCATE ON accelcal.certificate_documents
  FOR EACH STATEMENT EXECUTE FUNCTION accelcal.refuse_change();
CREATE TRIGGER calibrations_stay BEFORE UPDATE OR DELETE ON accelcal.calibrations
  FOR EACH ROW EXECUTE FUNCTION accelcal.refuse_change();
CREATE TRIGGER calibrations_stay_whole BEFORE TRUNCATE ON accelcal.calibrations
  FOR EACH STATEMENT EXECUTE FUNCTION accelcal.refuse_change();

-- Grants: everyone of the lab reads; a bench inserts what a publication is; a manager signs,
-- withdraws and keeps the equipment register.
GRANT SELECT ON ALL TABLES IN SCHEMA accelcal TO accelcal_bench, accelcal_manager;
GRANT INSERT ON accelcal.sessions, accelcal.session_sensors, accelcal.calibrations,
  accelcal.certificate_documents, accelcal.session_equipment TO accelcal_bench;
GRANT INSERT (certificate_number, seq, session_uuid, sensor_index) ON accelcal.certificates TO accelcal_bench;
GRANT INSERT (serial) ON accelcal.devices TO accelcal_bench;
GRANT UPDATE (status, withdrawn_reason) ON accelcal.certificates TO accelcal_manager;
GRANT INSERT ON accelcal.equipment, accelcal.equipment_certificates TO accelcal_manager;
GRANT UPDATE (kind, name) ON accelcal.equipment TO accelcal_manager;
GRANT UPDATE (certificate_prefix) ON accelcal.lab_settings TO accelcal_manager;

-- Row-level security: a bench inserts only its own sessions and their parts.
CREATE FUNCTION accelcal.session_is_mine(id uuid) RETURNS boolean LANGUAGE sql STABLE AS $$
  SELECT EXISTS (SELECT 1 FROM accelcal.sessions s WHERE s.session_uuid = id AND s.bench = current_user) $$;
CREATE FUNCTION accelcal.certificate_is_mine(number text) RETURNS boolean LANGUAGE sql STABLE AS $$
  SELECT EXISTS (SELECT 1 FROM accelcal.certificates c JOIN accelcal.sessions s USING (session_uuid)
                 WHERE c.certificate_number = number AND s.bench = current_user) $$;

)sql";

// Version 1's row-level security, one row a table a bench inserts into: everyone of the lab
// reads every row; a bench inserts only rows that pass `bench_check` (its own sessions and what
// hangs from them).
struct BenchInsertRule {
  std::string_view table;
  std::string_view bench_check;
};
constexpr BenchInsertRule kBenchInsertRules[] = {
    {"sessions", "bench = current_user"},
    {"session_sensors", "accelcal.session_is_mine(session_uuid)"},
    {"calibrations", "accelcal.session_is_mine(session_uuid)"},
    {"session_equipment", "accelcal.session_is_mine(session_uuid)"},
    {"certificates", "accelcal.session_is_mine(session_uuid)"},
    {"certificate_documents", "accelcal.certificate_is_mine(certificate_number)"},
};

// Version 1 whole: the register, then the rules above, then the one update a role may make of
// those tables (a manager's of a certificate's status).
std::string Version1() {
  std::string sql(kVersion1Register);
  for (const BenchInsertRule& r : kBenchInsertRules)
    sql += fmt::format(
        "ALTER TABLE accelcal.{0} ENABLE ROW LEVEL SECURITY;\n"
        "CREATE POLICY lab_reads ON accelcal.{0} FOR SELECT USING (true);\n"
        "CREATE POLICY bench_inserts_own ON accelcal.{0} FOR INSERT TO accelcal_bench\n"
        "  WITH CHECK ({1});\n",
        r.table, r.bench_check);
  sql +=
      "CREATE POLICY manager_sets_status ON accelcal.certificates FOR UPDATE TO accelcal_manager\n"
      "  USING (true) WITH CHECK (true);\n";
  return sql;
}

// Version 2: when a device or an item of equipment is due for recalibration. A device's
// interval is its type's, else the lab's default; it is due that long after its latest valid
// calibration (neither withdrawn, nor FAIL, nor INCOMPLETE), and at once when it has none.
// An item of equipment is due when its latest certificate runs out.
constexpr std::string_view kVersion2 = R"sql(
CREATE TABLE accelcal.device_types (
  device_type text PRIMARY KEY CHECK (device_type <> ''),
  recal_interval_days integer NOT NULL CHECK (recal_interval_days > 0));
ALTER TABLE accelcal.devices ADD COLUMN device_type text REFERENCES accelcal.device_types ON UPDATE CASCADE;
ALTER TABLE accelcal.lab_settings ADD COLUMN default_recal_interval_days integer NOT NULL DEFAULT 365
  CHECK (default_recal_interval_days > 0);

CREATE VIEW accelcal.device_due AS
SELECT d.serial, d.device_type,
       coalesce(t.recal_interval_days, s.default_recal_interval_days) AS recal_interval_days,
       v.certificate_number AS last_certificate_number,
       v.date_utc AS last_calibrated_utc,
       v.date_utc + make_interval(days => coalesce(t.recal_interval_days, s.default_recal_interval_days))
         AS due_utc
FROM accelcal.devices d
CROSS JOIN accelcal.lab_settings s
LEFT JOIN accelcal.device_types t USING (device_type)
LEFT JOIN LATERAL (
  SELECT c.date_utc, ce.certificate_number
  FROM accelcal.session_sensors ss
  JOIN accelcal.calibrations c USING (session_uuid, sensor_index)
  JOIN accelcal.certificates ce USING (session_uuid, sensor_index)
  WHERE ss.device_serial = d.serial AND ce.status <> 'withdrawn'
    AND c.verdict NOT IN ('FAIL', 'INCOMPLETE')
  ORDER BY c.date_utc DESC LIMIT 1) v ON true;

CREATE VIEW accelcal.equipment_due AS
SELECT e.equipment_id, e.kind, e.name, l.certificate_ref, l.calibrated_on, l.valid_until
FROM accelcal.equipment e
LEFT JOIN LATERAL (
  SELECT certificate_ref, calibrated_on, valid_until FROM accelcal.equipment_certificates ec
  WHERE ec.equipment_id = e.equipment_id ORDER BY valid_until DESC, calibrated_on DESC LIMIT 1) l ON true;

GRANT SELECT ON accelcal.device_types, accelcal.device_due, accelcal.equipment_due
  TO accelcal_bench, accelcal_manager;
GRANT INSERT, UPDATE ON accelcal.device_types TO accelcal_manager;
GRANT UPDATE (device_type) ON accelcal.devices TO accelcal_manager;
GRANT UPDATE (default_recal_interval_days) ON accelcal.lab_settings TO accelcal_manager;
)sql";

// Version 3: a device's calibrations as the lab's other tools read them, one row per
// certificate, withdrawn ones included (they stay: accelcal lab history shows them).
constexpr std::string_view kVersion3 = R"sql(
CREATE VIEW accelcal.device_history AS
SELECT ss.device_serial AS serial, ce.certificate_number, ce.seq, s.session_uuid, s.name AS session,
       s.bench, c.date_utc, c.verdict, ce.status, s.procedure, s.operator, s.place,
       ce.issued_utc, ce.approved_by, ce.approved_utc, ce.withdrawn_by, ce.withdrawn_utc, ce.withdrawn_reason
FROM accelcal.certificates ce
JOIN accelcal.calibrations c USING (session_uuid, sensor_index)
JOIN accelcal.session_sensors ss USING (session_uuid, sensor_index)
JOIN accelcal.sessions s USING (session_uuid);
GRANT SELECT ON accelcal.device_history TO accelcal_bench, accelcal_manager;
)sql";

}  // namespace

const std::vector<LabMigration>& LabMigrations() {
  static const std::string version1 = Version1();
  static const std::vector<LabMigration> migrations = {
      {1, "the register: devices, sessions, sensors, calibrations, certificates, equipment; roles", true,
       version1},
      {2, "recalibration due: device types and intervals, device_due and equipment_due", true, kVersion2},
      {3, "the device_history view", true, kVersion3},
  };
  return migrations;
}

}  // namespace accelcal

// LabStore::Publish: one session, whole, in one transaction (lab_store.h).
#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/uuid.h"
#include "accelcal/lab/detail/pg_connection.h"
#include "accelcal/lab/detail/pg_sql.h"
#include "accelcal/lab/lab_store.h"

namespace accelcal {

using detail::PgBytes;
using detail::PgConnection;
using detail::PgInt;
using detail::PgNull;
using detail::PgParam;
using detail::PgResult;
using detail::PgText;

namespace {

void Validate(const LabPublication& p) {
  if (!IsUuidText(p.session_uuid))
    throw Error(fmt::format("session {} has no identity the lab can key it by ('{}')", p.session_name,
                            p.session_uuid));
  if (p.sensors.empty()) throw Error(fmt::format("session {} has no calibration to publish", p.session_name));
  for (const LabSensorCalibration& s : p.sensors)
    if (s.device_serial.empty())
      throw Error(
          fmt::format("session {} names no device serial: the lab's register is by serial "
                      "(the wizard's welcome asks it)",
                      p.session_name));
}

PgParam Number(double value) {
  return std::isfinite(value) ? PgText(fmt::format("{:.17g}", value)) : PgNull();
}

// The session's row; false when the store holds it already (committed by an earlier run, or by a
// concurrent publisher that this insert waited for).
bool InsertSession(PgConnection& db, const LabPublication& p, std::string* published_utc) {
  const PgResult r = db.Exec(
      "INSERT INTO accelcal.sessions (session_uuid, name, procedure, source, operator, place, gravity, "
      "gravity_mps2, gravity_sigma_mps2, created_utc, finished_utc, accelcal_version) "
      "VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12) "
      "ON CONFLICT (session_uuid) DO NOTHING RETURNING " +
          detail::IsoUtc("published_utc"),
      {PgText(p.session_uuid), PgText(p.session_name), PgText(p.procedure), PgText(p.source),
       PgText(p.operator_name), PgText(p.place), PgText(p.gravity), Number(p.gravity_mps2),
       Number(p.gravity_sigma_mps2), PgText(p.created_utc), PgText(p.finished_utc),
       PgText(p.accelcal_version)});
  if (r.rows() == 0) return false;
  *published_utc = r.Text(0, 0);
  return true;
}

void InsertSensor(PgConnection& db, const std::string& uuid, const LabSensorCalibration& s) {
  db.Exec("INSERT INTO accelcal.devices (serial) VALUES ($1) ON CONFLICT (serial) DO NOTHING",
          {PgText(s.device_serial)});
  db.Exec(
      "INSERT INTO accelcal.session_sensors (session_uuid, sensor_index, device_serial) "
      "VALUES ($1, $2, $3)",
      {PgText(uuid), PgInt(s.sensor_index), PgText(s.device_serial)});
  db.Exec(
      "INSERT INTO accelcal.calibrations (session_uuid, sensor_index, calibration_json, "
      "calibration_sha256, verdict, date_utc) "
      "VALUES ($1, $2, $3, encode(sha256(convert_to($3, 'UTF8')), 'hex'), $4, $5)",
      {PgText(uuid), PgInt(s.sensor_index), PgText(s.calibration_json), PgText(s.verdict),
       PgText(s.date_utc)});
}

void InsertEquipment(PgConnection& db, const LabPublication& p) {
  for (const LabEquipmentUse& e : p.equipment)
    db.Exec(
        "INSERT INTO accelcal.session_equipment (session_uuid, role, equipment_id, name, "
        "uncertainty, traceability) VALUES ($1, $2, $3, $4, $5, $6)",
        {PgText(p.session_uuid), PgText(e.role), PgText(e.equipment_id), PgText(e.name),
         PgText(e.uncertainty), PgText(e.traceability)});
}

// Draws the sensor's number, renders its certificate with it, stores both.
LabIssuedCertificate IssueCertificate(PgConnection& db, const std::string& uuid,
                                      const LabSensorCalibration& s, const LabCertificateRenderer& render) {
  const PgResult drawn = db.Exec("SELECT seq, certificate_number FROM accelcal.draw_certificate_number()");
  LabIssuedCertificate issued;
  issued.sensor_index = s.sensor_index;
  issued.certificate_number = drawn.Text(0, 1);
  issued.documents = render(s, issued.certificate_number);
  db.Exec(
      "INSERT INTO accelcal.certificates (certificate_number, seq, session_uuid, sensor_index) "
      "VALUES ($1, $2, $3, $4)",
      {PgText(issued.certificate_number), PgText(drawn.Text(0, 0)), PgText(uuid), PgInt(s.sensor_index)});
  for (const LabDocument& d : issued.documents)
    db.Exec(
        "INSERT INTO accelcal.certificate_documents (certificate_number, media_type, content, sha256) "
        "VALUES ($1, $2, $3, encode(sha256($3), 'hex'))",
        {PgText(issued.certificate_number), PgText(d.media_type), PgBytes(d.bytes)});
  return issued;
}

// The store holds the session already: the same calibrations (else the session changed after it
// was published, and the lab keeps what it certified), and their certificates as stored.
std::vector<LabIssuedCertificate> HeldCertificates(PgConnection& db, const LabPublication& p,
                                                   std::string* published_utc) {
  const PgResult session = db.Exec(
      "SELECT " + detail::IsoUtc("published_utc") + ", bench FROM accelcal.sessions WHERE session_uuid = $1",
      {PgText(p.session_uuid)});
  *published_utc = session.Text(0, 0);
  std::vector<LabIssuedCertificate> held;
  for (const LabSensorCalibration& s : p.sensors) {
    const PgResult row = db.Exec(
        "SELECT ce.certificate_number, "
        "c.calibration_sha256 = encode(sha256(convert_to($3, 'UTF8')), 'hex') "
        "FROM accelcal.calibrations c JOIN accelcal.certificates ce USING (session_uuid, sensor_index) "
        "WHERE c.session_uuid = $1 AND c.sensor_index = $2",
        {PgText(p.session_uuid), PgInt(s.sensor_index), PgText(s.calibration_json)});
    if (row.rows() == 0)
      throw Error(
          fmt::format("session {} is in the lab's register (published by {} on {}) without a "
                      "certificate for sensor {}",
                      p.session_name, session.Text(0, 1), *published_utc, s.sensor_index));
    if (row.Text(0, 1) != "t")
      throw Error(
          fmt::format("session {} was published on {} as certificate {} with another calibration: "
                      "its calibration changed since, and the lab keeps what it certified (a "
                      "lab manager may withdraw {}; calibrate again in a new session)",
                      p.session_name, *published_utc, row.Text(0, 0), row.Text(0, 0)));
    LabIssuedCertificate c;
    c.sensor_index = s.sensor_index;
    c.certificate_number = row.Text(0, 0);
    held.push_back(std::move(c));
  }
  return held;
}

}  // namespace

LabPublishResult LabStore::Publish(const LabPublication& publication, const LabCertificateRenderer& render) {
  Validate(publication);
  LabPublishResult result;
  detail::PgTransaction transaction(*db_);
  if (!InsertSession(*db_, publication, &result.published_utc)) {
    result.certificates = HeldCertificates(*db_, publication, &result.published_utc);
    transaction.Commit();
    for (LabIssuedCertificate& c : result.certificates)
      c.documents = CertificateDocuments(c.certificate_number);
    return result;
  }
  for (const LabSensorCalibration& s : publication.sensors) InsertSensor(*db_, publication.session_uuid, s);
  InsertEquipment(*db_, publication);
  for (const LabSensorCalibration& s : publication.sensors)
    result.certificates.push_back(IssueCertificate(*db_, publication.session_uuid, s, render));
  transaction.Commit();
  result.newly_published = true;
  return result;
}

std::vector<LabDocument> LabStore::CertificateDocuments(const std::string& certificate_number) const {
  const PgResult r = db_->Exec(
      "SELECT media_type, content FROM accelcal.certificate_documents WHERE certificate_number = $1 "
      "ORDER BY media_type",
      {PgText(certificate_number)});
  std::vector<LabDocument> documents;
  for (int i = 0; i < r.rows(); ++i) documents.push_back({r.Text(i, 0), r.Bytes(i, 1)});
  return documents;
}

}  // namespace accelcal

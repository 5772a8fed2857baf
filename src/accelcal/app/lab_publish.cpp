#include "accelcal/app/lab_publish.h"

#include <fmt/core.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accelcal/app/report_files.h"
#include "accelcal/app/report_metadata.h"
#include "accelcal/base/version.h"
#include "accelcal/io/atomic_write.h"
#include "accelcal/report/report_html.h"
#include "accelcal/report/report_text.h"
#include "accelcal/session/session_catalog.h"

namespace accelcal {
namespace {

using Kind = SessionPublishOutcome::Kind;

std::vector<LabEquipmentUse> EquipmentUsed(const std::vector<EquipmentItem>& items) {
  std::vector<LabEquipmentUse> used;
  for (const EquipmentItem& item : items)
    used.push_back({std::string(InfoOf(item.role).key), item.identification, item.name,
                    DescribeUncertainty(item), item.traceability});
  return used;
}

LabPublication PublicationOf(const SessionInfo& info, const std::string& calibration_json,
                             const ReportInputs& in, const ReportModel& model) {
  LabPublication p;
  p.session_uuid = info.uuid;
  p.session_name = info.name;
  p.procedure = info.procedure;
  p.source = info.source;
  p.operator_name = info.operator_name;
  p.place = in.meta.place;
  p.gravity = in.calibration.gravity.Describe();
  p.gravity_mps2 = in.calibration.gravity.gravity_mps2;
  p.gravity_sigma_mps2 = in.calibration.gravity.sigma_mps2;
  p.created_utc = info.created_utc;
  p.finished_utc = info.updated_utc;
  p.accelcal_version = kAccelcalVersion;
  // One sensor per session today (a fixture of many boards adds more, each its own device).
  p.sensors.push_back(
      {0, info.device, calibration_json, std::string(VerdictToString(model.verdict)), in.meta.date_utc});
  p.equipment = EquipmentUsed(in.equipment);
  return p;
}

// The certificate as the report renders it, with the lab's number on it.
LabCertificateRenderer RendererOf(const ReportModel& model) {
  return [&model](const LabSensorCalibration&, const std::string& number) {
    ReportModel numbered = model;
    numbered.certificate.number = number;
    return std::vector<LabDocument>{{"text/html", RenderReportHtml(numbered)},
                                    {"text/plain", RenderReportText(numbered)}};
  };
}

// The numbers into the session, then the certificate beside it as the lab stored it.
void WriteBack(LabStore& lab, SessionStore& store, const LabPublishResult& published,
               SessionPublishOutcome* out) {
  for (const LabIssuedCertificate& c : published.certificates) {
    store.RecordLabCertificate(
        {c.sensor_index, c.certificate_number, lab.Identity(), published.published_utc});
    out->certificate_numbers.push_back(c.certificate_number);
    if (c.sensor_index != 0) continue;  // one sensor's report beside the session today
    for (const LabDocument& d : c.documents) {
      const char* extension = d.media_type == "text/html"    ? "html"
                              : d.media_type == "text/plain" ? "txt"
                                                             : nullptr;
      if (extension == nullptr) continue;
      const std::string path = ReportPathFor(store.path(), extension);
      WriteFileAtomically(path, d.bytes);
      out->files_written.push_back(path);
    }
  }
}

SessionPublishOutcome NotReady(SessionPublishOutcome out, std::string why) {
  out.kind = Kind::kNotReady;
  out.message = std::move(why);
  return out;
}

}  // namespace

SessionPublishOutcome PublishSession(LabStore& lab, SessionStore& store,
                                     const std::string& default_procedure_path) {
  SessionPublishOutcome out;
  out.path = store.path();
  try {
    const SessionInfo info = store.Info();
    out.name = info.name;
    if (info.state != SessionState::kDone)
      return NotReady(out, "not finished: the wizard has not reached its end (run it again to finish)");
    // A session of several sensors (a fixture, docs/fixtures.md) would need one publication
    // sensor per board, each under its own serial: not built yet. Refused rather than filed
    // under the fixture's name with its first board's calibration.
    if (const std::optional<Fixture> sensors = store.Sensors(); sensors && sensors->sensors.size() > 1)
      return NotReady(out, fmt::format("a session of {} sensors on a fixture: the lab's register takes a "
                                       "session of one sensor so far (each board's report: accelcal "
                                       "report {} --sensor N)",
                                       sensors->sensors.size(), store.path()));
    const std::optional<std::string> calibration_json = store.Result();
    if (!calibration_json) return NotReady(out, "no calibration: nothing to certify");
    if (info.device.empty())
      return NotReady(out,
                      "no device serial: the lab's register is by serial (the wizard's welcome asks it)");
    for (const LabCertificateMark& mark : store.LabCertificates())
      if (mark.lab.rfind("lab " + lab.LabId() + " ", 0) != 0)
        return NotReady(out,
                        fmt::format("already published to another lab's register, as certificate {} ({})",
                                    mark.certificate_number, mark.lab));
    ReportRequest request;  // the report as `accelcal report SESSION` makes it
    request.input = store.path();
    request.default_procedure_path = default_procedure_path;
    ReportInputs in = ReportInputsFor(request);
    in.meta.certificate_number.clear();  // the lab's number goes on by the renderer
    const ReportModel model = BuildReportModel(in);
    const LabPublishResult published =
        lab.Publish(PublicationOf(info, *calibration_json, in, model), RendererOf(model));
    out.kind = published.newly_published ? Kind::kPublished : Kind::kAlreadyPublished;
    WriteBack(lab, store, published, &out);
  } catch (const LabError& e) {
    out.kind = Kind::kFailed;
    out.lab_unreachable = e.unreachable();
    out.message = e.what();
  } catch (const Error& e) {
    // A store that took the session and a write-back that failed: the number is the lab's
    // still, and the next publish writes it (the store hands back what it holds).
    out.message = out.certificate_numbers.empty() ? e.what()
                                                  : fmt::format("{} (in the lab as {})", e.what(),
                                                                fmt::join(out.certificate_numbers, ", "));
    out.kind = Kind::kFailed;
  }
  return out;
}

std::vector<SessionPublishOutcome> PublishSessionFiles(LabStore& lab, const std::vector<std::string>& paths,
                                                       const std::string& default_procedure_path) {
  std::vector<SessionPublishOutcome> outcomes;
  std::string unreachable;
  for (const std::string& path : paths) {
    if (!unreachable.empty()) {
      SessionPublishOutcome waiting;
      waiting.path = path;
      waiting.kind = Kind::kFailed;
      waiting.lab_unreachable = true;
      waiting.message = "waits: " + unreachable;
      outcomes.push_back(std::move(waiting));
      continue;
    }
    try {
      SessionOpenOptions existing;
      existing.create_if_missing = false;
      const std::unique_ptr<SessionStore> store = SessionStore::Open(path, existing);
      outcomes.push_back(PublishSession(lab, *store, default_procedure_path));
    } catch (const Error& e) {
      SessionPublishOutcome failed;
      failed.path = path;
      failed.message = e.what();
      outcomes.push_back(std::move(failed));
    }
    if (outcomes.back().lab_unreachable) unreachable = outcomes.back().message;
  }
  return outcomes;
}

std::optional<SessionPublishOutcome> PublishIfLabConfigured(SessionStore& store,
                                                            const std::string& default_procedure_path) {
  if (!LabConfigured()) return std::nullopt;
  try {
    const std::unique_ptr<LabStore> lab = LabStore::ConnectQuickly();
    return PublishSession(*lab, store, default_procedure_path);
  } catch (const LabError& e) {
    SessionPublishOutcome waiting;
    waiting.path = store.path();
    waiting.name = store.Info().name;
    waiting.lab_unreachable = e.unreachable();
    waiting.message = fmt::format("{}; it waits for `accelcal lab publish`", e.what());
    return waiting;
  }
}

std::vector<std::string> UnpublishedSessions(const std::string& dir) {
  std::vector<std::string> backlog;
  for (const SessionInfo& s : ListSessions(dir).sessions)
    if (s.state == SessionState::kDone && s.has_result && s.num_lab_certificates == 0)
      backlog.push_back(s.path);
  return backlog;
}

std::string DescribeOutcome(const SessionPublishOutcome& o) {
  const std::string who = o.name.empty() ? o.path : o.name;
  const std::string numbers = fmt::format("{}", fmt::join(o.certificate_numbers, ", "));
  switch (o.kind) {
    case Kind::kPublished:
      return fmt::format("{}: published as certificate {}", who, numbers);
    case Kind::kAlreadyPublished:
      return fmt::format("{}: already in the lab's register as certificate {}", who, numbers);
    case Kind::kNotReady:
      return fmt::format("{}: not published, {}", who, o.message);
    case Kind::kFailed:
      break;
  }
  return fmt::format("{}: not published: {}", who, o.message);
}

}  // namespace accelcal

#include "accelcal/io/lab_register_json.h"

#include "accelcal/io/detail/json_values.h"

namespace accelcal {
namespace {

// "" -> null: an absent value, as every JSON of accelcal writes it.
nlohmann::json TextOrNull(const std::string& text) {
  return text.empty() ? nlohmann::json() : nlohmann::json(text);
}

nlohmann::json DaysOrNull(const std::optional<long>& days) {
  return days ? nlohmann::json(*days) : nlohmann::json();
}

}  // namespace

std::string LabHistoryJsonText(const LabHistory& h) {
  nlohmann::json j = {{"device", h.serial},
                      {"device_type", TextOrNull(h.device_type)},
                      {"calibrations", nlohmann::json::array()}};
  for (const LabHistoryEntry& e : h.entries)
    j["calibrations"].push_back({{"certificate_number", e.certificate_number},
                                 {"session", e.session},
                                 {"session_uuid", e.session_uuid},
                                 {"bench", e.bench},
                                 {"date_utc", e.date_utc},
                                 {"verdict", e.verdict},
                                 {"status", e.status},
                                 {"procedure", e.procedure},
                                 {"operator", e.operator_name},
                                 {"approved_by", TextOrNull(e.approved_by)},
                                 {"approved_utc", TextOrNull(e.approved_utc)},
                                 {"withdrawn_by", TextOrNull(e.withdrawn_by)},
                                 {"withdrawn_utc", TextOrNull(e.withdrawn_utc)},
                                 {"withdrawn_reason", TextOrNull(e.withdrawn_reason)}});
  return detail::JsonText(j) + "\n";
}

std::string LabDueJsonText(const LabDueList& due) {
  nlohmann::json j = {
      {"today", due.today}, {"within_days", due.within_days}, {"due", nlohmann::json::array()}};
  for (const LabDueItem& item : due.items)
    j["due"].push_back({{"kind", item.kind == LabDueItem::Kind::kDevice ? "device" : "equipment"},
                        {"id", item.id},
                        {"type", TextOrNull(item.type)},
                        {"name", TextOrNull(item.name)},
                        {"last", TextOrNull(item.last)},
                        {"last_date", TextOrNull(item.last_date)},
                        {"due_date", TextOrNull(item.due_date)},
                        {"days_left", DaysOrNull(item.days_left)}});
  return detail::JsonText(j) + "\n";
}

std::string LabEquipmentJsonText(const std::vector<LabEquipmentStatus>& equipment) {
  nlohmann::json j = {{"equipment", nlohmann::json::array()}};
  for (const LabEquipmentStatus& s : equipment)
    j["equipment"].push_back({{"id", s.id},
                              {"kind", TextOrNull(s.kind)},
                              {"name", TextOrNull(s.name)},
                              {"certificate_ref", TextOrNull(s.certificate_ref)},
                              {"calibrated_on", TextOrNull(s.calibrated_on)},
                              {"valid_until", TextOrNull(s.valid_until)},
                              {"days_left", DaysOrNull(s.days_left)},
                              {"registered", s.registered},
                              {"valid", s.valid()}});
  return detail::JsonText(j) + "\n";
}

}  // namespace accelcal

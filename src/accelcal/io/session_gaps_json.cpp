// The JSON form of SessionGaps (session/session_gaps.h): what a wizard session's result carries beside
// the calibration so that `accelcal report SESSION` gives the verdict the wizard gave.
#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/detail/json_values.h"

namespace accelcal {

using namespace detail;

nlohmann::json SessionGapsToJson(const SessionGaps& gaps) {
  nlohmann::json steps = nlohmann::json::array();
  for (const SessionGaps::Step& s : gaps.steps)
    steps.push_back({{"id", s.id}, {"title", s.title}, {"why", s.why}, {"required", s.required}});
  return {{"steps", steps}, {"identification", gaps.identification},
          {"gravity_ambiguity", gaps.gravity_ambiguity}};
}

SessionGaps SessionGapsFromJson(const nlohmann::json& j, const std::string& source) {
  if (!j.is_object()) FailField(source, "session_gaps", "must be an object");
  SessionGaps gaps;
  const nlohmann::json& steps = RequiredField(j, "steps", "session_gaps.", source);
  if (!steps.is_array()) FailField(source, "session_gaps.steps", "must be an array");
  for (size_t i = 0; i < steps.size(); ++i) {
    const std::string path = fmt::format("session_gaps.steps[{}].", i);
    if (!steps[i].is_object()) FailField(source, path, "must be an object");
    SessionGaps::Step s;
    s.id = OptionalString(steps[i], "id", path, source);
    s.title = OptionalString(steps[i], "title", path, source);
    s.why = OptionalString(steps[i], "why", path, source);
    s.required = OptionalBool(steps[i], "required", path, source, true);
    gaps.steps.push_back(s);
  }
  if (j.contains("identification") && !j["identification"].is_null()) {
    const nlohmann::json& ids = j["identification"];
    if (!ids.is_array()) FailField(source, "session_gaps.identification", "must be an array of strings");
    for (size_t i = 0; i < ids.size(); ++i) {
      if (!ids[i].is_string())
        FailField(source, fmt::format("session_gaps.identification[{}]", i), "must be a string");
      gaps.identification.push_back(ids[i].get<std::string>());
    }
  }
  gaps.gravity_ambiguity = OptionalString(j, "gravity_ambiguity", "session_gaps.", source);
  return gaps;
}

}  // namespace accelcal

#include "accelcal/io/export/export_result.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {

std::string NameOf(const nlohmann::json& e) {
  return e.contains("name") && e["name"].is_string() ? e["name"].get<std::string>() : e.dump();
}

const Effect& KnownEffect(const nlohmann::json& e) {
  const std::string name = NameOf(e);
  const Effect* effect = FindEffect(name);
  if (effect == nullptr)
    throw Error(fmt::format("the calibration lists the effect '{}', which this version of "
                            "accelcal does not know", name));
  return *effect;
}

const nlohmann::json& AdoptedEffect(const Calibration& cal, const std::string& name) {
  for (const nlohmann::json& e : cal.effects)
    if (NameOf(e) == name) return e;
  throw Error(fmt::format("the calibration has no effect '{}'", name));
}

}  // namespace

Eigen::Matrix3d CorrectionMatrix(const SensorModel& model) {
  return model.Misalignment() * model.scale_counts_per_mps2.cwiseInverse().asDiagonal();
}

std::vector<std::string> SensorEffectNames(const Calibration& cal) {
  std::vector<const Effect*> effects;
  for (const nlohmann::json& e : cal.effects) {
    const Effect& effect = KnownEffect(e);
    if (effect.CorrectsReadings()) effects.push_back(&effect);
  }
  std::vector<std::string> names;
  for (const Effect* effect : InCorrectionOrder(effects)) names.emplace_back(effect->Name());
  return names;
}

std::vector<std::string> SessionEffectNotes(const Calibration& cal) {
  std::vector<std::string> notes;
  for (const nlohmann::json& e : cal.effects) {
    const Effect& effect = KnownEffect(e);
    if (!effect.CorrectsReadings())
      notes.push_back(fmt::format("effect {} is not exported: an error of the calibration session "
                                  "(bench), not of the sensor's readings",
                                  effect.Name()));
  }
  return notes;
}

double EffectParameter(const Calibration& cal, const std::string& name, const std::string& key) {
  const nlohmann::json& e = AdoptedEffect(cal, name);
  if (!e.contains("parameters") || !e["parameters"].contains(key) ||
      !e["parameters"][key].is_number() || !std::isfinite(e["parameters"][key].get<double>()))
    throw Error(fmt::format("effect '{}': parameter '{}' is missing or not a finite number", name, key));
  return e["parameters"][key].get<double>();
}

double EffectReferenceTempC(const Calibration& cal, const std::string& name) {
  const nlohmann::json& e = AdoptedEffect(cal, name);
  if (!e.contains("reference") || !e["reference"].contains("temp_c") ||
      !e["reference"]["temp_c"].is_number() || !std::isfinite(e["reference"]["temp_c"].get<double>()))
    throw Error(fmt::format("effect '{}': reference.temp_c is missing", name));
  return e["reference"]["temp_c"].get<double>();
}

std::string ExportNumber(double value) { return fmt::format("{}", value); }

std::string DescribeOrigin(const Calibration& cal, const ExportContext& context) {
  auto or_unknown = [](const std::string& s) { return s.empty() ? std::string("unknown") : s; };
  return fmt::format("device {}, calibrated {}, from {}", or_unknown(context.device),
                     or_unknown(context.date_utc),
                     or_unknown(context.source.empty() ? cal.source : context.source));
}

}  // namespace accelcal

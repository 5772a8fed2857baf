#include "accelcal/io/export/calibration_csv.h"

#include <cmath>

#include <fmt/format.h>

namespace accelcal {
namespace {

std::string Row(const std::string& name, double value, double sigma, const std::string& unit) {
  return fmt::format("{},{},{},{}\r\n", CsvQuote(name), ExportNumber(value),
                     std::isfinite(sigma) ? ExportNumber(sigma) : std::string(), CsvQuote(unit));
}

double JsonNumberOr(const nlohmann::json& j, const char* group, const std::string& key, double fallback) {
  if (j.contains(group) && j[group].is_object() && j[group].contains(key) && j[group][key].is_number())
    return j[group][key].get<double>();
  return fallback;
}

std::string JsonStringOr(const nlohmann::json& j, const char* group, const std::string& key) {
  if (j.contains(group) && j[group].is_object() && j[group].contains(key) && j[group][key].is_string())
    return j[group][key].get<std::string>();
  return {};
}

}  // namespace

std::string CsvQuote(const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
  std::string quoted = "\"";
  for (char ch : field) {
    if (ch == '"') quoted += '"';
    quoted += ch;
  }
  return quoted + '"';
}

ExportResult ExportCalibrationCsv(const Calibration& cal) {
  ExportResult result;
  std::string& t = result.text;
  t += "name,value,sigma,unit\r\n";
  const auto value = cal.model.ToVector();
  const auto sigma = cal.uncertainty.ToVector();
  for (int i = 0; i < kNumBaseParameters; ++i)
    t += Row(std::string(ParameterName(i)), value(i), sigma(i), std::string(ParameterUnit(i)));
  for (const nlohmann::json& e : cal.effects) {
    if (!e.contains("name") || !e["name"].is_string() || !e.contains("parameters") ||
        !e["parameters"].is_object())
      continue;
    const std::string name = e["name"].get<std::string>();
    for (const auto& [key, v] : e["parameters"].items()) {
      if (!v.is_number()) continue;
      t += Row(name + "." + key, v.get<double>(), JsonNumberOr(e, "uncertainty", key, kNaN),
               JsonStringOr(e, "units", key));
    }
  }
  t += Row("gravity_mps2", cal.gravity.gravity_mps2, kNaN, "m/s^2");
  t += Row("residual_rms_mps2", cal.residual_rms_mps2, kNaN, "m/s^2");
  return result;
}

}  // namespace accelcal

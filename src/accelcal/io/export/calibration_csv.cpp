#include "accelcal/io/export/calibration_csv.h"

#include <cmath>

#include <fmt/format.h>

#include "accelcal/io/csv_fields.h"

namespace accelcal {
namespace {

// An empty field for a value that is not known (a residual RMS an older file lacks): never
// "nan" or "inf".
std::string OptionalNumber(double value) { return std::isfinite(value) ? ExportNumber(value) : std::string(); }

std::string Row(const std::string& name, double value, double sigma, const std::string& unit) {
  return fmt::format("{},{},{},{}\r\n", CsvQuote(name), OptionalNumber(value), OptionalNumber(sigma),
                     CsvQuote(unit));
}

}  // namespace

ExportResult ExportCalibrationCsv(const Calibration& cal) {
  ExportResult result;
  std::string& t = result.text;
  t += "name,value,sigma,unit\r\n";
  const auto value = cal.model.ToVector();
  const auto sigma = cal.uncertainty.ToVector();
  for (int i = 0; i < kNumBaseParameters; ++i)
    t += Row(std::string(ParameterName(i)), value(i), sigma(i), std::string(ParameterUnit(i)));
  for (const CalibrationEffect& e : cal.effects)
    for (const EffectParameter& p : e.parameters) t += Row(e.name + "." + p.name, p.value, p.sigma, p.unit);
  t += Row("gravity_mps2", cal.gravity.gravity_mps2, kNaN, "m/s^2");
  t += Row("residual_rms_mps2", cal.residual_rms_mps2, kNaN, "m/s^2");
  return result;
}

}  // namespace accelcal

#include "accelcal/io/export/export_result.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "accelcal/base/error.h"
#include "accelcal/base/safe_text.h"
#include "accelcal/calibration/diagnosis/effect.h"

namespace accelcal {
namespace {

const Effect& KnownEffect(const CalibrationEffect& e) {
  const Effect* effect = FindEffect(e.name);
  if (effect == nullptr)
    throw Error(fmt::format("the calibration lists the effect '{}', which this version of "
                            "accelcal does not know", e.name));
  return *effect;
}

}  // namespace

Eigen::Matrix3d CorrectionMatrix(const SensorModel& model) {
  return model.Misalignment() * model.scale_counts_per_mps2.cwiseInverse().asDiagonal();
}

std::vector<std::string> SensorEffectNames(const Calibration& cal) {
  std::vector<const Effect*> effects;
  for (const CalibrationEffect& e : cal.effects) {
    const Effect& effect = KnownEffect(e);
    if (effect.CorrectsReadings()) effects.push_back(&effect);
  }
  std::vector<std::string> names;
  for (const Effect* effect : InCorrectionOrder(effects)) names.emplace_back(effect->Name());
  return names;
}

std::vector<std::string> SessionEffectNotes(const Calibration& cal) {
  std::vector<std::string> notes;
  for (const CalibrationEffect& e : cal.effects) {
    const Effect& effect = KnownEffect(e);
    if (!effect.CorrectsReadings())
      notes.push_back(fmt::format("effect {} is not exported: an error of the calibration session "
                                  "(bench), not of the sensor's readings",
                                  effect.Name()));
  }
  return notes;
}

double EffectParameterValue(const Calibration& cal, const std::string& name, const std::string& key) {
  const CalibrationEffect* e = cal.FindEffect(name);
  if (e == nullptr) throw Error(fmt::format("the calibration has no effect '{}'", name));
  const EffectParameter* p = e->Find(key);
  if (p == nullptr || !std::isfinite(p->value))
    throw Error(fmt::format("effect '{}': parameter '{}' is missing or not a finite number", name, key));
  return p->value;
}

double EffectReferenceTempC(const Calibration& cal) {
  if (!std::isfinite(cal.reference.temp_c))
    throw Error("the calibration's temperature effects have no reference temperature (reference.temp_c)");
  return cal.reference.temp_c;
}

namespace {

// The last guard before a number reaches a file another program reads: "inf" and "nan" are
// never exported (a calibration read from a file is finite; a derived value may overflow).
void RequireFinite(double value) {
  if (!std::isfinite(value))
    throw Error(fmt::format("a value to export is not a finite number ({}): the calibration's "
                            "numbers are out of any sensor's range",
                            value));
}

}  // namespace

std::string ExportNumber(double value) {
  RequireFinite(value);
  return fmt::format("{}", value);
}

std::string ExportNumber9(double value) {
  RequireFinite(value);
  return fmt::format("{:.9g}", value);
}

std::string DescribeOrigin(const Calibration& cal, const ExportContext& context) {
  // Typed by someone, or a file's name: one line of printable text, whatever it holds.
  auto or_unknown = [](const std::string& s) { return s.empty() ? std::string("unknown") : DisplayText(s); };
  return fmt::format("device {}, calibrated {}, from {}", or_unknown(context.device),
                     or_unknown(context.date_utc),
                     or_unknown(context.source.empty() ? cal.source : context.source));
}

}  // namespace accelcal

// The diagnosis (calibration/diagnosis/diagnosis.h) in the technician's words: one plain
// sentence per effect with its size in bench units ("the turntable radius seems 3.0 mm longer
// than entered"), what to do about it with the recommended choice named, and no statistics (the
// BIC / AICc / LOO tables are the step's details, one key away).
#pragma once

#include <string>
#include <vector>

#include "accelcal/base/sensor_model.h"
#include "accelcal/calibration/diagnosis/diagnosis.h"

namespace accelcal {

// The effect in a plain sentence, lower case, no final period, its size in bench units from its
// final parameters (mm for radii, % for speed and sensitivity, counts at 1 g, per degC, per
// minute for the sensor's response, deg for a tilt): what the effect states
// (Effect::InBenchTerms, calibration/diagnosis/bench_statement.h), rendered here.
// `gravity_mps2` sizes the responses at 1 g. An effect that states nothing, or that this version
// does not know, is named with its parameters and units.
std::string EffectInPlainWords(const AdoptedEffect& effect, double gravity_mps2);

// The effect's name in words ("a wrong turntable radius", "a bent response"; Effect::PlainName,
// of the library or of a rival explanation); the name itself when unknown.
std::string PlainEffectName(const std::string& effect_name);
// `text` with each of `effect_names` replaced by its PlainEffectName.
std::string WithPlainEffectNames(std::string text, const std::vector<std::string>& effect_names);

// True when the effect is an error of the bench during the calibration (radius, speed, tilt;
// Effect::IsBenchError): "correct it and refit"; false for a property of the sensor or an
// unknown effect: "add it to the calibration".
bool IsBenchError(const std::string& effect_name);

struct DiagnosisWords {
  std::vector<std::string> lines;  // what was found, one sentence a line (front ends wrap them)
  // The question when effects were found: "The turntable radius seems 3.0 mm longer than
  // entered: correct it and refit (recommended), or keep the basic model?"; else what happens.
  std::string prompt;
  std::string recommended_action;  // the Enter key's, short: "refit (recommended)"
  bool asks = false;               // there is a choice (effects were found)
};

DiagnosisWords DiagnosisInPlainWords(const DiagnosisReport& report, double gravity_mps2);

}  // namespace accelcal

// How firmware corrects a reading for an effect of the sensor: the effect's part of the C header
// that `accelcal export-cal --to c-header` writes (io/export/c_header.h). The effect states it
// (Effect::InC); the header adds the parts the effects share and refuses, by its name, a sensor
// effect that has none, rather than write a header that corrects readings otherwise than
// `accelcal apply` does.
//
// The statements run inside accelcal_correct, in correction order (Effect::CorrectionStage), on
// `ACCELCAL_REAL d[3]`, the reading minus the bias b (counts), which they turn into what the base
// model should see; `int j` is declared. They may read their own constants, K as
// `accelcal_scale_counts_per_mps2[3]` (counts per m/s^2) when `reads_scale`, and `dt_c`, the
// sensor's temperature minus the effects' reference (degC), when the effect ReadsTemperature()
// (accelcal_correct then takes the temperature). C99, clean under -Wall -Wextra -pedantic.
#pragma once

#include <string>
#include <vector>

namespace accelcal {

struct CCorrection {
  // One `static const ACCELCAL_REAL` of the header holding some of the effect's parameters.
  struct Constant {
    std::string comment;                  // the comment line above it, without /* */; empty: none
    std::string identifier;               // "accelcal_quadratic_counts_per_mps2_sq"
    std::vector<std::string> parameters;  // the effect's parameters it holds, in order: one makes
                                          // a scalar, more an array
  };
  std::vector<Constant> constants;
  std::string statements;                   // whole lines, each indented by two spaces
  bool reads_scale = false;                 // reads accelcal_scale_counts_per_mps2
  std::vector<std::string> math_functions;  // of <math.h> it calls ("sqrt"): link with -lm
};

}  // namespace accelcal

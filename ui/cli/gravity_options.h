// The gravity flags shared by the subcommands that need local gravity:
// --gravity G (a measured value, "9.78030", "9.78030+-0.00002", or "standard") |
// --latitude DEG [--altitude M]; default standard gravity (the wizard asks at its welcome, with
// these as the default answer).
#pragma once

#include <CLI/CLI.hpp>

#include "accelcal/base/gravity.h"

namespace accelcal::cli {

struct GravityFlags {
  std::string gravity_text;  // as app/wizard/gravity_input.h reads it
  double latitude_deg = 0.0;
  double altitude_m = 0.0;
  CLI::Option* gravity = nullptr;   // borrowed from the App, which outlives the flags
  CLI::Option* latitude = nullptr;
  CLI::Option* altitude = nullptr;

  void Bind(CLI::App& app);
  // The chosen gravity; throws accelcal::Error when it fails validation.
  GravitySpec Resolve() const;
  // A gravity flag was given (--gravity or --latitude), as typed ("--latitude 0"); empty: none.
  std::string Given() const;
};

}  // namespace accelcal::cli

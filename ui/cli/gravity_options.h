// The gravity flags shared by the subcommands that need local gravity:
// --gravity G | --latitude DEG [--altitude M]; default standard gravity.
#pragma once

#include <CLI/CLI.hpp>

#include "accelcal/base/gravity.h"

namespace accelcal::cli {

struct GravityFlags {
  double gravity_mps2 = 0.0;
  double latitude_deg = 0.0;
  double altitude_m = 0.0;
  CLI::Option* gravity = nullptr;   // borrowed from the App, which outlives the flags
  CLI::Option* latitude = nullptr;
  CLI::Option* altitude = nullptr;

  void Bind(CLI::App& app);
  // The chosen gravity; throws accelcal::Error when it fails validation.
  GravitySpec Resolve() const;
};

}  // namespace accelcal::cli

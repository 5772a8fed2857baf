// Reading a virtual-bench scenario (acquire/sim/scenario.h) from its TOML file.
#pragma once

#include <string>
#include <string_view>

#include "accelcal/acquire/sim/scenario.h"

namespace accelcal::sim {

// Parses a scenario from TOML text. `source_name` names it in errors. Throws InputError
// (FILE:LINE:COLUMN) on a syntax error, a missing or unknown key, a value of the wrong type or
// out of range (negative noise, unknown kind, radial axis parallel to the up axis, ...).
Scenario ParseScenario(std::string_view toml_text, const std::string& source_name);

// The truth of a simulated session (`accelcal simulate --truth`): the scenario's nine parameters
// and gravity, as JSON text {"bias_counts": [..], "scale_counts_per_mps2": [..],
// "misalignment_rad": {"yz", "zy", "zx"}, "gravity_mps2"}.
std::string ScenarioTruthJsonText(const Scenario& scenario);

// Reads and parses a scenario file. Throws Error when it cannot be read, InputError as above.
Scenario LoadScenario(const std::string& path);

}  // namespace accelcal::sim

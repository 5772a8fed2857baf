// `accelcal simulate`: run a virtual-bench scenario and write what the bench recorded.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

namespace accelcal::cli {

struct SimulateOptions {
  std::string scenario_path;          // scenario TOML file
  std::string output_path = "-";      // capture set (or recording); "-" = standard output
  bool recording = false;             // write one continuous recording instead of captures
  std::optional<std::uint64_t> seed;  // overrides [bench] seed
  std::string truth_path;             // when set: the true parameters as JSON go here
};

// Runs the simulation; "-" output goes to `stdout_stream`. Throws accelcal::Error/InputError.
void RunSimulate(const SimulateOptions& options, std::ostream& stdout_stream);

}  // namespace accelcal::cli

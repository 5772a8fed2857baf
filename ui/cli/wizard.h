// `accelcal wizard`: the guided calibration on a live source (the virtual bench by default).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "accelcal/base/gravity.h"

namespace accelcal::cli {

struct WizardCommandOptions {
  std::string source = "sim";       // source spec (source_spec.h)
  double speed = 1.0;               // sim: simulated seconds per wall second; 0 = flat out
  std::optional<std::uint64_t> seed;  // sim: overrides the scenario's seed
  std::string scenario_path;        // sim: scenario file; empty = the built-in default bench
  std::string procedure_path;       // empty = the shipped full_calibration.toml (shipped_files.h)
  std::string session_path;         // empty = a new session named by the time
  bool plain = false;               // line mode even on a terminal
  // On a bench pointed at a lab (LabConfigured): the welcome's equipment check, and the finished
  // session published at the end. --no-lab: neither.
  bool no_lab = false;
  std::string place;                // offered at the welcome (the lab, the bench)
  double fixed_duration_s = 0.0;    // > 0: every capture this long (no plan by the target), s
  std::string bench_control;        // HOST:PORT of a remote virtual bench's controls (tests)
  std::string vehicle_calibration = "undo";  // mavlink: undo | as-is
  GravitySpec gravity;
  std::string gravity_flag;         // the gravity flag as given ("--latitude 0"); empty: none
  // Several sensors at once (issue 31; cli/wizard_fixture.h): sim's --sensors N boards, a
  // fixture file, or a text link's --columns naming N column triples.
  int sensors = 0;
  std::string fixture_path;
  std::string columns;
};

// Runs the wizard to its end or until the operator leaves; returns the exit status.
int RunWizard(const WizardCommandOptions& options);

}  // namespace accelcal::cli

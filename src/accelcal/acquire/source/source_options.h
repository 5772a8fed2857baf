// Options for OpenSource (source_spec.h): how every source judges its stream (dead link, gaps,
// malformed lines), how fd-based links retry, how a file is paced, and the simulator's settings.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/acquire/source/sim_options.h"

namespace accelcal {

struct SourceOptions {
  // No sample for this long (wall clock) => the link is reported dead, s. Raise it for slow
  // loggers; it must exceed a few sample intervals.
  double dead_after_s = 2.0;
  // An interval in t longer than gap_factor times the median interval is a gap. > 1.
  double gap_factor = 3.0;
  // Serial and TCP: first wait before reopening a lost link, s; it doubles up to
  // reconnect_max_s on each failed attempt and resets once the link is open again.
  double reconnect_initial_s = 0.1;
  double reconnect_max_s = 5.0;
  // A line longer than this with no end of line is garbage (binary noise, a wrong baud rate):
  // counted as one malformed line and skipped up to the next newline, bytes. >= 64.
  long max_line_bytes = 256;
  // Every source but sim: how its lines are read (columns, a header row, skipped rows, a rate
  // for a stream without time, the readings' unit); the default is the protocol's
  // `t ax ay az [temp_c]`. Its own max_line_bytes is replaced by the one above.
  SampleFormat format;
  // file: true => deliver samples paced by their t (as they were recorded); false => as fast
  // as they can be read.
  bool realtime = false;
  // "-": the file descriptor read as standard input (0; tests pass a pipe). Not closed.
  int stdin_fd = 0;
  // sim: the bench (read from its file by io/scenario_file.h); empty => the built-in
  // sim::DefaultScenario().
  std::optional<sim::Scenario> scenario;
  // sim: overrides the scenario's [bench] seed.
  std::optional<std::uint64_t> seed;
  SimOptions sim;

  // Empty when valid; otherwise what is wrong.
  std::string Validate() const;
};

}  // namespace accelcal

// The flags of the one sample reader (base/sample_reader.h), shared by every subcommand that
// reads recordings or sample streams (fit --recording, apply, allan, noise --record, record):
// --columns LIST, --skip-rows N, --rate-hz HZ, --unit counts|m/s^2|g [--counts-per-unit N],
// --no-repair-time; for a ROS bag (bags/bag_sample_stream.h), --topic NAME and
// --bag-time header|receive.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "accelcal/base/sample_format.h"

namespace accelcal::cli {

struct SampleFormatFlags {
  std::string columns;
  long skip_rows = 0;
  double rate_hz = kNaN;
  std::string unit = "counts";
  double counts_per_unit = kNaN;
  bool no_repair_time = false;
  std::string topic;               // a bag's IMU topic; empty: its only one
  std::string bag_time = "header";  // header | receive
  CLI::Option* unit_option = nullptr;  // borrowed from the App, which outlives the flags

  // `what` names the input in the help ("the recording", "standard input").
  void Bind(CLI::App& app, const std::string& what);
  // The format; throws accelcal::Error for a bad column list or unit.
  SampleFormat Resolve() const;
};

}  // namespace accelcal::cli

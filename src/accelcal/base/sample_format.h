// How to read a table of samples (a recording, a logger's CSV, a stream): the options of the one
// sample reader (sample_reader.h), which the `--columns`, `--skip-rows`, `--rate-hz` and
// `--unit` flags of `fit --recording`, `apply`, `allan`, `noise` and `record` fill.
//
// Units: rate in Hz; line lengths in bytes. Readings are counts unless `unit` says otherwise.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/sample_columns.h"

namespace accelcal {

// What the ax, ay, az columns hold. The model is in ADC counts (sensor_model.h): bias in counts,
// scale in counts per m/s^2. A logger that already converted its readings to m/s^2 or g hides
// its counts; such readings are taken as counts of 1/counts_per_unit of their unit (by default
// a thousandth: 1 count = 0.001 m/s^2, or 1 mg), so the fitted bias is in those counts and the
// scale is counts_per_unit (per m/s^2; per g: counts_per_unit / g) when the logger's own
// conversion is exact. A calibration made this way records the unit (calibration.h) and is
// applied to readings in the same unit.
struct ReadingUnit {
  enum class Kind { kCounts, kMps2, kG };
  Kind kind = Kind::kCounts;
  double counts_per_unit = 1.0;  // counts: 1; m/s^2, g: > 0 (default 1000)

  static constexpr double kDefaultCountsPerUnit = 1000.0;

  bool is_counts() const { return kind == Kind::kCounts; }
  // "counts", "m/s^2", "g".
  std::string Name() const;
  // "counts", or "m/s^2, taken as counts of 0.001 m/s^2".
  std::string Describe() const;
  // Empty when valid; otherwise what is wrong.
  std::string Validate() const;
};

// "counts" / "m/s^2" (also "mps2", "m/s2") / "g": the unit with its default counts_per_unit;
// nullopt for anything else.
std::optional<ReadingUnit> StringToReadingUnit(std::string_view text);

struct SampleFormat {
  // The file's columns in order; empty: named by a header row when the file has one, else the
  // protocol's `t ax ay az [temp_c]`.
  std::vector<NamedColumn> columns;
  // Leading lines to ignore, whatever they hold (metadata before the data), lines.
  long skip_rows = 0;
  // Samples per second: t = row index / rate_hz (the first data row at t = 0), replacing any t
  // column; NaN: t from the t column (which must then exist), Hz.
  double rate_hz = kNaN;
  ReadingUnit unit;
  // The unit was declared (`--unit`): a header that states another one is then not an error.
  bool unit_declared = false;
  // Non-empty: every data line must carry a temperature, and one without is malformed with
  // this message (`apply` with a calibration that corrects for temperature).
  std::string require_temp_c;
  // Time stamps that repeat because they were printed with too few digits are spread within
  // their rounding step (sample_time_check.h); false: every repeat is an error.
  bool repair_ties = true;
  // A line longer than this, bytes: in a file an error (binary data, or not a recording), in a
  // live stream one malformed line skipped to the next newline. >= 64.
  long max_line_bytes = 4096;
  // A bag (bags/bag_sample_stream.h) rather than a table: its IMU topic (empty: the only one it
  // holds), and t from the bag's receive times instead of the messages' header stamps.
  struct BagChoice {
    std::string topic;
    bool receive_time = false;
  };
  BagChoice bag;

  // Empty when valid; otherwise what is wrong.
  std::string Validate() const;
  // The columns were given (rather than found in a header or taken as the protocol's).
  bool HasExplicitLayout() const { return !columns.empty(); }
};

}  // namespace accelcal

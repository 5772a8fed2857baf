#include "accelcal/base/sample_format.h"

#include <cmath>

#include <fmt/format.h>

namespace accelcal {

std::string ReadingUnit::Name() const {
  switch (kind) {
    case Kind::kCounts: return "counts";
    case Kind::kMps2: return "m/s^2";
    case Kind::kG: return "g";
  }
  return "counts";
}

std::string ReadingUnit::Describe() const {
  if (is_counts()) return "counts";
  return fmt::format("{}, taken as counts of {} {}", Name(), 1.0 / counts_per_unit, Name());
}

std::string ReadingUnit::Validate() const {
  if (is_counts() && counts_per_unit != 1.0) return "readings in counts take no counts_per_unit";
  if (!(std::isfinite(counts_per_unit) && counts_per_unit > 0.0))
    return fmt::format("counts per {} must be a positive number", Name());
  return {};
}

std::optional<ReadingUnit> StringToReadingUnit(std::string_view text) {
  if (text == "counts") return ReadingUnit{};
  if (text == "m/s^2" || text == "mps2" || text == "m/s2")
    return ReadingUnit{ReadingUnit::Kind::kMps2, ReadingUnit::kDefaultCountsPerUnit};
  if (text == "g") return ReadingUnit{ReadingUnit::Kind::kG, ReadingUnit::kDefaultCountsPerUnit};
  return std::nullopt;
}

std::string SampleFormat::Validate() const {
  if (!columns.empty()) {
    if (std::string e = CheckColumnLayout(columns); !e.empty()) return "columns: " + e;
  }
  if (skip_rows < 0) return "skip_rows must be >= 0";
  if (!std::isnan(rate_hz) && !(std::isfinite(rate_hz) && rate_hz > 0.0))
    return "the rate must be a positive number of Hz";
  if (std::string e = unit.Validate(); !e.empty()) return "unit: " + e;
  if (max_line_bytes < 64) return "max_line_bytes must be >= 64";
  return {};
}

}  // namespace accelcal

#include "accelcal/base/sensor_columns.h"

#include <array>

#include <fmt/core.h>

namespace accelcal {
namespace {

std::string_view Trimmed(std::string_view name) {
  while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
  while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
  return name;
}

}  // namespace

std::vector<std::vector<NamedColumn>> SplitSensorColumns(std::string_view text,
                                                         std::string* error) {
  std::vector<NamedColumn> line;
  for (size_t start = 0; start <= text.size();) {
    size_t comma = text.find(',', start);
    if (comma == std::string_view::npos) comma = text.size();
    const std::string_view name = Trimmed(text.substr(start, comma - start));
    const std::optional<NamedColumn> c = ColumnFromListName(name);
    if (!c) {
      *error = fmt::format("--columns: unknown column '{}' (known: t, t_ms, t_us, t_ns, ax, ay, "
                           "az, temp_c, and - for a column to ignore)", name);
      return {};
    }
    line.push_back(*c);
    start = comma + 1;
  }
  // owner[i]: the sensor column i belongs to (-1: shared or ignored).
  std::array<int, 6> seen{};
  std::vector<int> owner(line.size(), -1);
  for (size_t i = 0; i < line.size(); ++i) {
    const int kind = static_cast<int>(line[i].column);
    if (line[i].column != SampleColumn::kT && line[i].column != SampleColumn::kIgnore)
      owner[i] = seen[static_cast<size_t>(kind)];
    ++seen[static_cast<size_t>(kind)];
  }
  const int ax = seen[static_cast<size_t>(SampleColumn::kAx)];
  const int ay = seen[static_cast<size_t>(SampleColumn::kAy)];
  const int az = seen[static_cast<size_t>(SampleColumn::kAz)];
  const int temps = seen[static_cast<size_t>(SampleColumn::kTempC)];
  if (ax == 0 || ax != ay || ax != az) {
    *error = fmt::format("--columns: each sensor needs ax, ay and az (named {}, {} and {} times)",
                         ax, ay, az);
    return {};
  }
  if (seen[static_cast<size_t>(SampleColumn::kT)] > 1) {
    *error = "--columns: t is named twice (one time column serves every sensor)";
    return {};
  }
  if (temps > 1 && temps != ax) {
    *error = fmt::format("--columns: temp_c named {} times: once for all the sensors, or once "
                         "per sensor ({})", temps, ax);
    return {};
  }
  std::vector<std::vector<NamedColumn>> sensors(static_cast<size_t>(ax), line);
  for (int k = 0; k < ax; ++k) {
    std::vector<NamedColumn>& mine = sensors[static_cast<size_t>(k)];
    for (size_t i = 0; i < line.size(); ++i) {
      const bool shared_temp = line[i].column == SampleColumn::kTempC && temps == 1;
      if (owner[i] >= 0 && owner[i] != k && !shared_temp) mine[i] = {SampleColumn::kIgnore, 1.0};
    }
  }
  return sensors;
}

}  // namespace accelcal

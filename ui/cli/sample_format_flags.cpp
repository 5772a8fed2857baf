#include "cli/cli_checks.h"
#include "cli/sample_format_flags.h"

#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::cli {

void SampleFormatFlags::Bind(CLI::App& app, const std::string& what) {
  app.add_option("--columns", columns,
                 fmt::format("The columns of {} in order, comma-separated: t (s; or t_ms, t_us, "
                             "t_ns), ax, ay, az, temp_c, or - for a column to ignore, e.g. "
                             "t,-,-,-,ax,ay,az. Default: named by a header row, else t ax ay az "
                             "[temp_c]", what));
  app.add_option("--skip-rows", skip_rows,
                 "Leading lines to ignore (metadata before the data)")
      ->check(NonNegative());
  app.add_option("--rate-hz", rate_hz,
                 "Samples per second: t = row / rate (no time column needed; replaces one)")
      ->check(Positive());
  unit_option = app.add_option(
      "--unit", unit,
      "What ax, ay, az hold: counts (raw ADC), or m/s^2 or g for a logger that converted them "
      "(taken as counts of 1/1000 of the unit: bias in those counts, scale 1000 per unit when "
      "the logger's own conversion is exact)")
      ->check(CLI::IsMember({"counts", "m/s^2", "mps2", "g"}))
      ->capture_default_str();
  app.add_option("--counts-per-unit", counts_per_unit,
                 "With --unit m/s^2 or g: counts per unit (default 1000)")
      ->check(Positive());
  app.add_flag("--no-repair-time", no_repair_time,
               "Refuse repeated time stamps instead of spreading rounded ones within their step");
  app.add_option("--topic", topic,
                 "A ROS bag's IMU topic (sensor_msgs/Imu); default: its only one (several: "
                 "they are listed)");
  app.add_option("--bag-time", bag_time,
                 "A ROS bag's t: header (each message's header stamp) or receive (the time the "
                 "bag recorded it)")
      ->check(CLI::IsMember({"header", "receive"}))
      ->capture_default_str();
}

SampleFormat SampleFormatFlags::Resolve() const {
  SampleFormat f;
  if (!columns.empty()) {
    std::string error;
    f.columns = ParseColumnList(columns, &error);
    if (!error.empty()) throw Error(error);
  }
  f.skip_rows = skip_rows;
  f.rate_hz = rate_hz;
  const std::optional<ReadingUnit> u = StringToReadingUnit(unit);
  if (!u) throw Error(fmt::format("--unit {}: expected counts, m/s^2 or g", unit));
  f.unit = *u;
  f.unit_declared = unit_option != nullptr && unit_option->count() > 0;
  if (std::isfinite(counts_per_unit)) {
    if (f.unit.is_counts()) throw Error("--counts-per-unit needs --unit m/s^2 or g");
    f.unit.counts_per_unit = counts_per_unit;
  }
  f.repair_ties = !no_repair_time;
  f.bag.topic = topic;
  f.bag.receive_time = bag_time == "receive";
  if (std::string e = f.Validate(); !e.empty()) throw Error(e);
  return f;
}

}  // namespace accelcal::cli

// The columns of a table of samples (a recording, a logger's CSV, a capture set): what each one
// holds, the names users give it, and the `--columns` list that names them in order.
//
// Canonical names: t (time, s), ax ay az (raw readings), temp_c (degC), and "-" for a column to
// ignore. A time column may carry its unit: t_ms, t_us, t_ns (milli-, micro-, nanoseconds).
//
// Header recognition (RecognizeColumnName): a header cell is reduced to lower-case letters and
// digits, a unit in brackets or parentheses dropped ("AccX [m/s^2]" -> "accx"), and compared
// with common spellings:
//   time     t, time, timestamp, time_s, sec, seconds, (and _ms/_us/_ns forms: time_ms,
//            timestamp_ms, millis, t_us, micros, ...)
//   ax       ax, a_x, accx, acc_x, accel_x, accelx, accelerometer_x, acceleration_x,
//            linear_acceleration_x, xacc, x_accel (likewise ay, az)
//   temp_c   temp_c, temp, temperature, tempc, temp_degc, die_temp, imu_temp
// Everything else (gyroscope, magnetometer, counters, ...) is a column to ignore; the reader
// lists those it ignored. The unit written in a header cell ("[m/s^2]", "(g)", "_mps2") is
// reported as a hint (HeaderUnitHint), never applied silently.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace accelcal {

enum class SampleColumn : std::uint8_t { kT, kAx, kAy, kAz, kTempC, kIgnore };

// "t", "ax", "ay", "az", "temp_c", "-".
std::string_view SampleColumnName(SampleColumn column);

// A column as named: what it holds and, for time, the factor from its unit to seconds.
struct NamedColumn {
  SampleColumn column = SampleColumn::kIgnore;
  double time_to_s = 1.0;  // t: 1 (s), 1e-3 (ms), 1e-6 (us), 1e-9 (ns)
};

// The canonical name of a column list entry: "t", "t_ms", "ax", ... "-".
std::string ColumnListName(const NamedColumn& column);

// What a header cell names (see the header comment); kIgnore when none of the spellings.
NamedColumn RecognizeColumnName(std::string_view cell);

// The unit a header cell states, reduced to "m/s^2" or "g"; empty when it states none (or one
// not recognised).
std::string HeaderUnitHint(std::string_view cell);

// One name of a `--columns` list (t, t_s, t_ms, t_us, t_ns, ax, ay, az, temp_c, -); nullopt for
// any other.
std::optional<NamedColumn> ColumnFromListName(std::string_view name);

// Parses a `--columns` list: canonical names (t, t_ms, t_us, t_ns, ax, ay, az, temp_c, -)
// separated by commas. Each of ax, ay, az exactly once; t and temp_c at most once.
// Returns the columns, or sets *error (and returns empty) with what is wrong.
std::vector<NamedColumn> ParseColumnList(std::string_view text, std::string* error);

// Empty when `columns` is a usable layout (ax, ay, az each exactly once; t, temp_c at most
// once); otherwise what is wrong, naming the columns by `names` (same size) when given.
std::string CheckColumnLayout(const std::vector<NamedColumn>& columns,
                              const std::vector<std::string>& names = {});

}  // namespace accelcal

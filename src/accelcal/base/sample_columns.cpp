#include "accelcal/base/sample_columns.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

namespace accelcal {
namespace {

bool IsAlnum(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}
char Lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

// A header cell taken apart: its words (lower-case letters and digits, split at anything else)
// and what it had in brackets or parentheses (its unit, usually).
struct CellWords {
  std::vector<std::string> words;
  std::string bracketed;  // lower-case, as written (without the brackets)
};

CellWords SplitCell(std::string_view cell) {
  CellWords out;
  std::string word;
  int depth = 0;
  for (char c : cell) {
    if (c == '[' || c == '(') {
      ++depth;
      continue;
    }
    if (c == ']' || c == ')') {
      depth = std::max(0, depth - 1);
      continue;
    }
    if (depth > 0) {
      if (c != ' ') out.bracketed += Lower(c);
      continue;
    }
    if (IsAlnum(c)) {
      word += Lower(c);
    } else if (!word.empty()) {
      out.words.push_back(std::move(word));
      word.clear();
    }
  }
  if (!word.empty()) out.words.push_back(std::move(word));
  return out;
}

// Seconds per unit for a time unit word ("s", "ms", "us", "ns"); 0 when it is none.
double TimeUnit(std::string_view w) {
  if (w == "s" || w == "sec" || w == "secs") return 1.0;
  if (w == "ms" || w == "msec") return 1e-3;
  if (w == "us" || w == "usec" || w == "\xc2\xb5s") return 1e-6;
  if (w == "ns" || w == "nsec") return 1e-9;
  return 0.0;
}

std::string AccelUnit(std::string_view w) {
  if (w == "m/s^2" || w == "m/s2" || w == "m/s\xc2\xb2" || w == "mps2" || w == "ms2" ||
      w == "ms^-2" || w == "m*s^-2")
    return "m/s^2";
  if (w == "g") return "g";
  return {};
}

// Words that only qualify a reading and say nothing of which one it is.
bool IsQualifier(std::string_view w) {
  return w == "raw" || w == "counts" || w == "lsb" || w == "adc" || w == "mps2" || w == "ms2" ||
         w == "g" || w == "value" || w == "val";
}

std::string Join(const std::vector<std::string>& words, size_t n) {
  std::string s;
  for (size_t i = 0; i < n && i < words.size(); ++i) s += words[i];
  return s;
}

constexpr std::array<std::string_view, 12> kAccelPrefixes = {
    "a", "acc", "accel", "accl", "accelerometer", "acceleration", "linearacceleration", "linacc",
    "imuacc", "imuaccel", "accelerometers", "accelerations"};

// "ax" -> kAx ...; kIgnore when `joined` is not an accelerometer axis.
SampleColumn AccelAxis(std::string_view joined) {
  if (joined.empty()) return SampleColumn::kIgnore;
  const auto axis_of = [](char c) {
    return c == 'x' ? SampleColumn::kAx
           : c == 'y' ? SampleColumn::kAy
           : c == 'z' ? SampleColumn::kAz
                      : SampleColumn::kIgnore;
  };
  for (std::string_view p : kAccelPrefixes) {
    if (joined.size() == p.size() + 1 && joined.substr(0, p.size()) == p)
      return axis_of(joined.back());  // "accx"
    if (joined.size() == p.size() + 1 && joined.substr(1) == p && p != "a")
      return axis_of(joined.front());  // "xacc"
  }
  return SampleColumn::kIgnore;
}

bool IsTimeWord(std::string_view w) {
  return w == "t" || w == "time" || w == "timestamp" || w == "times" || w == "ts" ||
         w == "sec" || w == "seconds" || w == "elapsed" || w == "elapsedtime" ||
         w == "timesec";
}

bool IsTemperatureWord(std::string_view w) {
  return w == "temp" || w == "tempc" || w == "temperature" || w == "temperaturec" ||
         w == "tempdegc" || w == "temperaturedegc" || w == "dietemp" || w == "imutemp" ||
         w == "tmp" || w == "degc";
}

}  // namespace

std::string_view SampleColumnName(SampleColumn column) {
  switch (column) {
    case SampleColumn::kT: return "t";
    case SampleColumn::kAx: return "ax";
    case SampleColumn::kAy: return "ay";
    case SampleColumn::kAz: return "az";
    case SampleColumn::kTempC: return "temp_c";
    case SampleColumn::kIgnore: return "-";
  }
  return "-";
}

std::string ColumnListName(const NamedColumn& column) {
  if (column.column != SampleColumn::kT || column.time_to_s == 1.0)
    return std::string(SampleColumnName(column.column));
  if (column.time_to_s == 1e-3) return "t_ms";
  if (column.time_to_s == 1e-6) return "t_us";
  if (column.time_to_s == 1e-9) return "t_ns";
  return fmt::format("t (x{})", column.time_to_s);
}

NamedColumn RecognizeColumnName(std::string_view cell) {
  CellWords c = SplitCell(cell);
  NamedColumn out;
  if (c.words.empty()) return out;
  // A trailing time unit ("time_ms", "t us") or one in brackets ("time (ms)").
  double time_unit = TimeUnit(c.bracketed);
  std::vector<std::string> words = c.words;
  if (words.size() > 1 && TimeUnit(words.back()) > 0.0) {
    const double u = TimeUnit(words.back());
    words.pop_back();
    if (IsTimeWord(Join(words, words.size()))) time_unit = u;
    else words.push_back(c.words.back());
  }
  const std::string joined_all = Join(words, words.size());
  if (joined_all == "millis" || joined_all == "timems" || joined_all == "timestampms") {
    return {SampleColumn::kT, 1e-3};
  }
  if (joined_all == "micros" || joined_all == "timeus" || joined_all == "timestampus") {
    return {SampleColumn::kT, 1e-6};
  }
  if (IsTimeWord(joined_all)) return {SampleColumn::kT, time_unit > 0.0 ? time_unit : 1.0};
  // Temperature in degC only ("temp_f" is another quantity).
  if (IsTemperatureWord(joined_all) && c.bracketed.find('f') == std::string::npos)
    return {SampleColumn::kTempC, 1.0};
  while (words.size() > 1 && IsQualifier(words.back())) words.pop_back();
  while (words.size() > 1 && IsQualifier(words.front())) words.erase(words.begin());
  out.column = AccelAxis(Join(words, words.size()));
  return out;
}

std::string HeaderUnitHint(std::string_view cell) {
  const CellWords c = SplitCell(cell);
  if (std::string u = AccelUnit(c.bracketed); !u.empty()) return u;
  if (c.words.size() > 1) return AccelUnit(c.words.back());
  return {};
}

std::optional<NamedColumn> ColumnFromListName(std::string_view name) {
  if (name == "-") return NamedColumn{SampleColumn::kIgnore, 1.0};
  if (name == "t" || name == "t_s") return NamedColumn{SampleColumn::kT, 1.0};
  if (name == "t_ms") return NamedColumn{SampleColumn::kT, 1e-3};
  if (name == "t_us") return NamedColumn{SampleColumn::kT, 1e-6};
  if (name == "t_ns") return NamedColumn{SampleColumn::kT, 1e-9};
  if (name == "ax") return NamedColumn{SampleColumn::kAx, 1.0};
  if (name == "ay") return NamedColumn{SampleColumn::kAy, 1.0};
  if (name == "az") return NamedColumn{SampleColumn::kAz, 1.0};
  if (name == "temp_c") return NamedColumn{SampleColumn::kTempC, 1.0};
  return std::nullopt;
}

std::vector<NamedColumn> ParseColumnList(std::string_view text, std::string* error) {
  std::vector<NamedColumn> columns;
  std::vector<std::string> names;
  size_t start = 0;
  while (start <= text.size()) {
    size_t comma = text.find(',', start);
    if (comma == std::string_view::npos) comma = text.size();
    std::string_view name = text.substr(start, comma - start);
    while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
    while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
    const std::optional<NamedColumn> c = ColumnFromListName(name);
    if (!c) {
      *error = fmt::format("--columns: unknown column '{}' (known: t, t_ms, t_us, t_ns, ax, ay, "
                           "az, temp_c, and - for a column to ignore)", name);
      return {};
    }
    columns.push_back(*c);
    names.emplace_back(name);
    start = comma + 1;
  }
  if (std::string e = CheckColumnLayout(columns, names); !e.empty()) {
    *error = "--columns: " + e;
    return {};
  }
  return columns;
}

std::string CheckColumnLayout(const std::vector<NamedColumn>& columns,
                              const std::vector<std::string>& names) {
  const auto name_of = [&](size_t i) {
    return i < names.size() ? names[i] : std::string(SampleColumnName(columns[i].column));
  };
  for (SampleColumn wanted : {SampleColumn::kT, SampleColumn::kAx, SampleColumn::kAy,
                              SampleColumn::kAz, SampleColumn::kTempC}) {
    std::vector<std::string> found;
    for (size_t i = 0; i < columns.size(); ++i)
      if (columns[i].column == wanted) found.push_back(fmt::format("'{}'", name_of(i)));
    const bool required = wanted == SampleColumn::kAx || wanted == SampleColumn::kAy ||
                          wanted == SampleColumn::kAz;
    if (required && found.empty())
      return fmt::format("no column for {} (the accelerometer needs ax, ay and az)",
                         SampleColumnName(wanted));
    if (found.size() > 1)
      return fmt::format("{} columns name {}: {}", found.size(), SampleColumnName(wanted),
                         fmt::join(found, ", "));
  }
  return {};
}

}  // namespace accelcal

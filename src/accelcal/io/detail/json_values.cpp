#include "accelcal/io/detail/json_values.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/io/detail/read_file.h"

namespace accelcal::detail {

json JsonNumber(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json JsonTriad(const Eigen::Vector3d& v) {
  return json::array({JsonNumber(v.x()), JsonNumber(v.y()), JsonNumber(v.z())});
}

json JsonTriadOrNull(const Eigen::Vector3d& v) {
  if (!v.allFinite()) return nullptr;
  return json::array({v.x(), v.y(), v.z()});
}

json JsonNumbers(const std::vector<double>& values) {
  json out = json::array();
  for (double v : values) out.push_back(JsonNumber(v));
  return out;
}

std::string JsonText(const json& j) { return j.dump(2, ' ', false, json::error_handler_t::replace); }

namespace {

// Line and column (from 1) of the byte at `at`.
std::pair<long, long> LineColumn(const std::string& text, size_t at) {
  at = std::min(at, text.size());
  long line = 1, col = 1;
  for (size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col};
}

// nlohmann's overflow message quotes the literal ("number overflow parsing '1e999'"): find it
// in the text to name its place.
[[noreturn]] void FailNumberOverflow(const std::string& text, const std::string& source, const std::string& what) {
  const size_t open = what.find('\'');
  const size_t close = open == std::string::npos ? open : what.find('\'', open + 1);
  const std::string literal = close == std::string::npos ? std::string() : what.substr(open + 1, close - open - 1);
  const size_t at = literal.empty() ? std::string::npos : text.find(literal);
  const auto [line, col] = at == std::string::npos ? std::pair<long, long>{0, 0} : LineColumn(text, at);
  throw InputError(source, line, col,
                   fmt::format("the number {} is beyond a double's range", literal.substr(0, 40)));
}

}  // namespace

json ParseJsonText(const std::string& text, const std::string& source) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    // nlohmann reports a byte offset; turn it into line and column.
    const auto [line, col] = LineColumn(text, e.byte == 0 ? 0 : e.byte - 1);
    throw InputError(source, line, col, "not valid JSON");
  } catch (const json::out_of_range& e) {
    FailNumberOverflow(text, source, e.what());
  } catch (const json::exception&) {
    throw InputError(source, 0, 0, "not valid JSON");
  }
}

json ReadJsonFile(const std::string& path) { return ParseJsonText(ReadWholeFile(path), path); }

void FailField(const std::string& source, const std::string& field, const std::string& what) {
  throw InputError(source, 0, 0, fmt::format("field '{}': {}", field, what));
}

const json& RequiredField(const json& j, const std::string& key, const std::string& path,
                          const std::string& source) {
  if (!j.is_object() || !j.contains(key)) FailField(source, path + key, "missing");
  return j.at(key);
}

double RequiredFinite(const json& j, const std::string& key, const std::string& path,
                      const std::string& source) {
  const json& v = RequiredField(j, key, path, source);
  if (!v.is_number()) FailField(source, path + key, "must be a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) FailField(source, path + key, "must be finite");
  return d;
}

double OptionalFinite(const json& j, const std::string& key, const std::string& path,
                      const std::string& source) {
  if (!j.is_object() || !j.contains(key) || j.at(key).is_null()) return NAN;
  const json& v = j.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>())) FailField(source, path + key, "must be a finite number");
  return v.get<double>();
}

std::string OptionalString(const json& j, const std::string& key, const std::string& path,
                           const std::string& source, const std::string& fallback) {
  if (!j.is_object() || !j.contains(key) || j.at(key).is_null()) return fallback;
  if (!j.at(key).is_string()) FailField(source, path + key, "must be a string");
  return j.at(key).get<std::string>();
}

long OptionalInteger(const json& j, const std::string& key, const std::string& path,
                     const std::string& source, long fallback) {
  if (!j.is_object() || !j.contains(key) || j.at(key).is_null()) return fallback;
  if (!j.at(key).is_number_integer()) FailField(source, path + key, "must be an integer");
  return j.at(key).get<long>();
}

bool OptionalBool(const json& j, const std::string& key, const std::string& path,
                  const std::string& source, bool fallback) {
  if (!j.is_object() || !j.contains(key) || j.at(key).is_null()) return fallback;
  if (!j.at(key).is_boolean()) FailField(source, path + key, "must be true or false");
  return j.at(key).get<bool>();
}

std::vector<double> NumberArray(const json& j, const std::string& key, const std::string& path,
                                const std::string& source, bool null_ok) {
  std::vector<double> out;
  if (!j.is_object() || !j.contains(key) || j.at(key).is_null()) return out;
  const json& a = j.at(key);
  if (!a.is_array()) FailField(source, path + key, "must be an array of numbers");
  for (size_t i = 0; i < a.size(); ++i) {
    if (null_ok && a[i].is_null()) {
      out.push_back(NAN);
      continue;
    }
    if (!a[i].is_number() || !std::isfinite(a[i].get<double>()))
      FailField(source, fmt::format("{}{}[{}]", path, key, i), "must be a finite number");
    out.push_back(a[i].get<double>());
  }
  return out;
}

}  // namespace accelcal::detail

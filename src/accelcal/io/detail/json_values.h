// The JSON helpers every file format of io/ shares: numbers written with NaN as null (JSON has no
// NaN), and strict reading that names the file and the field of whatever is wrong, never a
// library's raw exception text.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace accelcal::detail {

using nlohmann::json;

// A number, or null when it is not finite.
json JsonNumber(double value);
// [x, y, z], each null when not finite.
json JsonTriad(const Eigen::Vector3d& v);
// [x, y, z], or null when any is not finite.
json JsonTriadOrNull(const Eigen::Vector3d& v);
// Each value, null where not finite.
json JsonNumbers(const std::vector<double>& values);

// `j` as text (2-space indent). A string that is not well-formed UTF-8 (a device name typed
// on a Latin-1 terminal) has each ill-formed byte written as U+FFFD instead of making the
// library throw: text is replaced at input (base/safe_text.h), this is the last guard.
std::string JsonText(const json& j);

// Parses `text` as JSON; InputError(source, line, column, "not valid JSON") otherwise, and
// InputError(source, line, column, "the number N is beyond a double's range") for a literal
// such as 1e999 (never a library's exception text).
json ParseJsonText(const std::string& text, const std::string& source);
// Reads the file `path` (once: a pipe works) and parses it.
json ReadJsonFile(const std::string& path);

// Strict reading. Every failure is an InputError naming `source` and the field's path
// ("captures[3].kind").
[[noreturn]] void FailField(const std::string& source, const std::string& field, const std::string& what);
// j[key]; missing (or j not an object) fails.
const json& RequiredField(const json& j, const std::string& key, const std::string& path,
                          const std::string& source);
// A finite number at j[key]; missing, of another type or not finite fails.
double RequiredFinite(const json& j, const std::string& key, const std::string& path,
                      const std::string& source);
// A finite number at j[key], NaN when absent or null; another type fails.
double OptionalFinite(const json& j, const std::string& key, const std::string& path,
                      const std::string& source);
// A string at j[key], `fallback` when absent or null; another type fails.
std::string OptionalString(const json& j, const std::string& key, const std::string& path,
                           const std::string& source, const std::string& fallback = {});
// An integer at j[key], `fallback` when absent or null; another type fails.
long OptionalInteger(const json& j, const std::string& key, const std::string& path,
                     const std::string& source, long fallback);
// A boolean at j[key], `fallback` when absent or null; another type fails.
bool OptionalBool(const json& j, const std::string& key, const std::string& path,
                  const std::string& source, bool fallback);
// An array of finite numbers at j[key] (empty when absent or null); with `null_ok`, null
// entries read as NaN.
std::vector<double> NumberArray(const json& j, const std::string& key, const std::string& path,
                                const std::string& source, bool null_ok);

}  // namespace accelcal::detail

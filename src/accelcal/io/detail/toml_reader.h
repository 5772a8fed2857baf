// Reading one TOML table field by field, with errors that point at the offending text.
// Internal to the core (toml++ is a private dependency): nothing in ui/ includes this.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include <toml++/toml.h>
#include <Eigen/Core>

namespace accelcal::detail {

// Which values a number may take.
enum class NumberRange { kAny, kNonNegative, kPositive };

// Parses a whole TOML document; a syntax error becomes an InputError at its line and column.
toml::table ParseTomlDocument(std::string_view text, const std::string& source_name);

// Reads the fields of `table`, remembering the keys read so Finish() can refuse the others
// (a typo in a key then fails loudly instead of silently taking the default).
// Every failure throws accelcal::InputError at the node's source position.
class TomlTableReader {
 public:
  // `path` names the table in messages ("bench", "capture 3"); `source_name` is the file.
  // Borrows `table` and `source_name`: both must outlive the reader.
  TomlTableReader(const toml::table& table, std::string path, const std::string& source_name);

  bool Has(std::string_view key) const { return table_.contains(key); }

  // A missing key returns `fallback`, or throws when there is none (the key is required).
  double Number(std::string_view key, std::optional<double> fallback,
                NumberRange range = NumberRange::kAny);
  std::int64_t Integer(std::string_view key, std::optional<std::int64_t> fallback);
  bool Bool(std::string_view key, std::optional<bool> fallback);
  std::string String(std::string_view key, std::optional<std::string> fallback);
  // An array of exactly three numbers.
  Eigen::Vector3d Vector3(std::string_view key, std::optional<Eigen::Vector3d> fallback,
                          NumberRange range = NumberRange::kAny);
  // An array of exactly two numbers.
  Eigen::Vector2d Vector2(std::string_view key, std::optional<Eigen::Vector2d> fallback,
                          NumberRange range = NumberRange::kAny);
  // A sub-table, or nullptr when absent.
  const toml::table* Table(std::string_view key);
  // An array of tables ([[key]]); nullptr when absent.
  const toml::array* ArrayOfTables(std::string_view key);

  // Throws for the first key that was not read.
  void Finish() const;

  // Throws InputError at `node` with "PATH.KEY: message" (or "PATH: message" for an empty key).
  // Fail at `key`'s node, or at the table when the key is absent (a default value that
  // conflicts with another key: the file has no node of its own to point at).
  [[noreturn]] void FailKey(std::string_view key, const std::string& message) const;
  [[noreturn]] void Fail(const toml::node& node, std::string_view key,
                         const std::string& message) const;
  // The node of `key`, or nullptr; marks the key as read.
  const toml::node* Get(std::string_view key);

 private:
  std::string Name(std::string_view key) const;
  [[noreturn]] void Missing(std::string_view key) const;
  void CheckRange(const toml::node& node, std::string_view key, double value,
                  NumberRange range) const;

  const toml::table& table_;
  std::string path_;
  const std::string& source_name_;
  std::set<std::string, std::less<>> read_;
};

}  // namespace accelcal::detail

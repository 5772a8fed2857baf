#include "accelcal/io/detail/toml_reader.h"

#include <cmath>

#include "accelcal/base/error.h"

namespace accelcal::detail {
namespace {

std::string_view TypeName(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time: return "a date/time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

// TOML keeps integers and floats apart; a quantity in SI units may be typed either way.
std::optional<double> AsNumber(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  return std::nullopt;
}

}  // namespace

TomlTableReader::TomlTableReader(const toml::table& table, std::string path,
                                 const std::string& source_name)
    : table_(table), path_(std::move(path)), source_name_(source_name) {}

std::string TomlTableReader::Name(std::string_view key) const {
  if (key.empty()) return path_;
  if (path_.empty()) return std::string(key);
  return path_ + "." + std::string(key);
}

void TomlTableReader::Fail(const toml::node& node, std::string_view key,
                           const std::string& message) const {
  const toml::source_position at = node.source().begin;
  throw InputError(source_name_, at.line, at.column, Name(key) + ": " + message);
}

void TomlTableReader::FailKey(std::string_view key, const std::string& message) const {
  const toml::node* node = table_.get(key);
  Fail(node != nullptr ? *node : static_cast<const toml::node&>(table_), key, message);
}

void TomlTableReader::Missing(std::string_view key) const {
  Fail(table_, key, "required key is missing");
}

const toml::node* TomlTableReader::Get(std::string_view key) {
  const toml::node* node = table_.get(key);
  if (node != nullptr) read_.emplace(key);
  return node;
}

void TomlTableReader::CheckRange(const toml::node& node, std::string_view key, double value,
                                 NumberRange range) const {
  if (!std::isfinite(value)) Fail(node, key, "must be a finite number");
  if (range == NumberRange::kNonNegative && value < 0.0) Fail(node, key, "must not be negative");
  if (range == NumberRange::kPositive && value <= 0.0) Fail(node, key, "must be positive");
}

double TomlTableReader::Number(std::string_view key, std::optional<double> fallback,
                               NumberRange range) {
  const toml::node* node = Get(key);
  if (node == nullptr) {
    if (!fallback) Missing(key);
    return *fallback;
  }
  const std::optional<double> value = AsNumber(*node);
  if (!value) Fail(*node, key, "expected a number, got " + std::string(TypeName(*node)));
  CheckRange(*node, key, *value, range);
  return *value;
}

std::int64_t TomlTableReader::Integer(std::string_view key, std::optional<std::int64_t> fallback) {
  const toml::node* node = Get(key);
  if (node == nullptr) {
    if (!fallback) Missing(key);
    return *fallback;
  }
  const auto* value = node->as_integer();
  if (value == nullptr)
    Fail(*node, key, "expected an integer, got " + std::string(TypeName(*node)));
  return value->get();
}

bool TomlTableReader::Bool(std::string_view key, std::optional<bool> fallback) {
  const toml::node* node = Get(key);
  if (node == nullptr) {
    if (!fallback) Missing(key);
    return *fallback;
  }
  const auto* value = node->as_boolean();
  if (value == nullptr)
    Fail(*node, key, "expected true or false, got " + std::string(TypeName(*node)));
  return value->get();
}

std::string TomlTableReader::String(std::string_view key, std::optional<std::string> fallback) {
  const toml::node* node = Get(key);
  if (node == nullptr) {
    if (!fallback) Missing(key);
    return *fallback;
  }
  const auto* value = node->as_string();
  if (value == nullptr) Fail(*node, key, "expected a string, got " + std::string(TypeName(*node)));
  return value->get();
}

Eigen::Vector3d TomlTableReader::Vector3(std::string_view key,
                                         std::optional<Eigen::Vector3d> fallback,
                                         NumberRange range) {
  const toml::node* node = Get(key);
  if (node == nullptr) {
    if (!fallback) Missing(key);
    return *fallback;
  }
  const auto* array = node->as_array();
  if (array == nullptr || array->size() != 3) {
    Fail(*node, key, "expected an array of three numbers [x, y, z]");
  }
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    const toml::node& element = *array->get(static_cast<std::size_t>(i));
    const std::optional<double> value = AsNumber(element);
    if (!value) Fail(element, key, "expected a number, got " + std::string(TypeName(element)));
    CheckRange(element, key, *value, range);
    v(i) = *value;
  }
  return v;
}

Eigen::Vector2d TomlTableReader::Vector2(std::string_view key,
                                         std::optional<Eigen::Vector2d> fallback,
                                         NumberRange range) {
  const toml::node* node = Get(key);
  if (node == nullptr) {
    if (!fallback) Missing(key);
    return *fallback;
  }
  const auto* array = node->as_array();
  if (array == nullptr || array->size() != 2) Fail(*node, key, "expected an array of two numbers");
  Eigen::Vector2d v;
  for (int i = 0; i < 2; ++i) {
    const toml::node& element = *array->get(static_cast<std::size_t>(i));
    const std::optional<double> value = AsNumber(element);
    if (!value) Fail(element, key, "expected a number, got " + std::string(TypeName(element)));
    CheckRange(element, key, *value, range);
    v(i) = *value;
  }
  return v;
}

const toml::table* TomlTableReader::Table(std::string_view key) {
  const toml::node* node = Get(key);
  if (node == nullptr) return nullptr;
  const auto* table = node->as_table();
  if (table == nullptr) Fail(*node, key, "expected a table, got " + std::string(TypeName(*node)));
  return table;
}

const toml::array* TomlTableReader::ArrayOfTables(std::string_view key) {
  const toml::node* node = Get(key);
  if (node == nullptr) return nullptr;
  const auto* array = node->as_array();
  if (array == nullptr || !array->is_array_of_tables()) {
    Fail(*node, key, "expected an array of tables ([[" + std::string(key) + "]])");
  }
  return array;
}

void TomlTableReader::Finish() const {
  for (auto&& [key, node] : table_) {
    if (read_.find(key.str()) != read_.end()) continue;
    const toml::source_position at = key.source().begin;
    throw InputError(source_name_, at.line, at.column,
                     "unknown key '" + Name(key.str()) + "' (misspelt?)");
  }
}

toml::table ParseTomlDocument(std::string_view text, const std::string& source_name) {
  try {
    return toml::parse(text, std::string_view(source_name));
  } catch (const toml::parse_error& e) {
    throw InputError(source_name, e.source().begin.line, e.source().begin.column,
                     std::string(e.description()));
  }
}

}  // namespace accelcal::detail

#include "accelcal/base/error.h"

#include <fmt/core.h>

namespace accelcal {
namespace {

std::string Where(const std::string& file, long line, long column) {
  if (line <= 0) return file;
  if (column <= 0) return fmt::format("{}:{}", file, line);
  return fmt::format("{}:{}:{}", file, line, column);
}

}  // namespace

InputError::InputError(std::string file, long line, long column, const std::string& message)
    : Error(fmt::format("{}: {}", Where(file, line, column), message)),
      file_(std::move(file)), line_(line), column_(column), message_(message) {}

}  // namespace accelcal

#include "accelcal/error.h"

namespace accelcal {
namespace {

std::string Where(const std::string& file, long line, long column) {
  std::string where = file;
  if (line > 0) {
    where += ":" + std::to_string(line);
    if (column > 0) where += ":" + std::to_string(column);
  }
  return where;
}

}  // namespace

InputError::InputError(std::string file, long line, long column, const std::string& message)
    : Error(Where(file, line, column) + ": " + message),
      file_(std::move(file)), line_(line), column_(column), message_(message) {}

}  // namespace accelcal

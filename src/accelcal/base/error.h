// Errors the core reports to its callers. The core never prints: it throws these (or returns a
// summary that says what went wrong) and the front end decides how to show them.
#pragma once

#include <stdexcept>
#include <string>

namespace accelcal {

// A job that cannot be done (bad data, a fit that cannot determine the parameters, I/O failure).
// what() is one line, fit for "accelcal: error: <what>".
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Malformed input: names where. what() reads "FILE:LINE:COLUMN: MESSAGE" (compiler style, so
// editors jump to it); line and column are 1-based, 0 when not applicable.
class InputError : public Error {
 public:
  InputError(std::string file, long line, long column, const std::string& message);

  const std::string& file() const { return file_; }
  long line() const { return line_; }
  long column() const { return column_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  long line_ = 0;
  long column_ = 0;
  std::string message_;
};

}  // namespace accelcal

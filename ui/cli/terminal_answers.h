// The operator's answers when stdin carries the samples (`--source -`): they come from the
// controlling terminal, /dev/tty, never from the sample stream (issue 17, item 3).
#pragma once

#include <istream>
#include <memory>
#include <string>

namespace accelcal::cli {

class TerminalAnswers {
 public:
  // Opens the controlling terminal. Throws accelcal::Error, with the reason and what to do,
  // when the process has none (a pipe in a script, cron, CI).
  TerminalAnswers();
  ~TerminalAnswers();
  TerminalAnswers(const TerminalAnswers&) = delete;
  TerminalAnswers& operator=(const TerminalAnswers&) = delete;

  std::istream& in() { return *in_; }
  int fd() const { return fd_; }

 private:
  int fd_ = -1;                  // owned; closed in the destructor
  std::unique_ptr<std::streambuf> buf_;
  std::unique_ptr<std::istream> in_;
};

}  // namespace accelcal::cli

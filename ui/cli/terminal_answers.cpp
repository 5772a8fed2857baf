#include "cli/terminal_answers.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ext/stdio_filebuf.h>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::cli {

TerminalAnswers::TerminalAnswers() {
  fd_ = ::open("/dev/tty", O_RDONLY | O_CLOEXEC);
  if (fd_ < 0)
    throw Error(fmt::format(
        "--source - reads the samples from stdin, so the answers must come from a terminal, and "
        "this process has none (/dev/tty: {}): run the wizard from a terminal, or give the "
        "samples as file:PATH (a recording) or tcp:HOST:PORT",
        std::strerror(errno)));
  // A libstdc++ stream over the descriptor (std::ifstream cannot hand out its descriptor, which
  // line mode polls while the wizard is busy). The descriptor stays ours.
  buf_ = std::make_unique<__gnu_cxx::stdio_filebuf<char>>(fd_, std::ios::in, 1);
  in_ = std::make_unique<std::istream>(buf_.get());
}

TerminalAnswers::~TerminalAnswers() {
  in_.reset();
  buf_.reset();  // stdio_filebuf over a descriptor does not close it
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace accelcal::cli

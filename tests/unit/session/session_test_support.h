// A test fixture for the session-store tests: a fresh directory per test (named after the test,
// so parallel test processes do not meet) with a session path in it, removed afterwards; and the
// open options the tests use.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/session/session_store.h"

namespace accelcal::testing {

class SessionDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("accelcal_session_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    path_ = (dir_ / "s.db").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  static SessionOpenOptions Writer() {
    SessionOpenOptions o;
    o.procedure = "bench_default";
    o.source = "sim";
    return o;
  }
  static SessionOpenOptions Reader() {
    SessionOpenOptions o;
    o.read_only = true;
    return o;
  }

  std::filesystem::path dir_;
  std::string path_;
};

// The crash tests' harness: forks a child that runs `work(fd)`, which commits items forever and
// writes each item's number on a line to `fd` once its commit has returned (so whatever the
// parent reads must be in the store); kills it with SIGKILL `delay_us` microseconds after it
// starts, or after its first line when `after_first_line` (so a slow machine cannot starve the
// test); returns the numbers it reported.
inline std::set<long> RunAndKill(const std::function<void(int fd)>& work, int delay_us,
                                 bool after_first_line) {
  int fds[2];
  if (pipe(fds) != 0) {
    ADD_FAILURE() << "pipe failed";
    return {};
  }
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    work(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  std::string text;
  char buffer[256];
  auto read_some = [&] {
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n > 0) text.append(buffer, static_cast<size_t>(n));
    return n > 0;
  };
  if (after_first_line)
    while (text.find('\n') == std::string::npos && read_some()) {
    }
  usleep(static_cast<useconds_t>(delay_us));
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  while (read_some()) {
  }
  close(fds[0]);
  std::set<long> reported;
  size_t start = 0;
  for (size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    reported.insert(std::stol(text.substr(start, end - start)));
  return reported;
}

}  // namespace accelcal::testing

// A test fixture for the session-store tests: a fresh directory per test (named after the test,
// so parallel test processes do not meet) with a session path in it, removed afterwards; and the
// open options the tests use.
#pragma once

#include <unistd.h>

#include <filesystem>
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

}  // namespace accelcal::testing

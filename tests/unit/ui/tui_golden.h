// The TUI's golden screens (tests/data/tui/NAME.txt), shared by the tui_*_test.cpp files.
// ACCELCAL_UPDATE_GOLDEN=1 rewrites them from what is rendered: review every diff.
#pragma once

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tui/render.h"

namespace accelcal::ui {

inline void ExpectGolden(const std::string& name, const ScreenModel& screen) {
  const std::string path = std::string(ACCELCAL_SOURCE_DIR) + "/tests/data/tui/" + name + ".txt";
  const std::string text = screen.Text();
  const char* update = std::getenv("ACCELCAL_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") std::ofstream(path) << text;
  std::ifstream in(path);
  ASSERT_TRUE(in) << "missing golden file " << path;
  std::stringstream golden;
  golden << in.rdbuf();
  EXPECT_EQ(golden.str(), text) << name << " rendered as:\n" << text;
}

}  // namespace accelcal::ui

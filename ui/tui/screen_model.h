// A fixed-size grid of ASCII cells, each with a role: what the TUI draws, kept free of curses so
// that view tests render into it and compare its text with golden files (docs/STYLE.md: FTXUI's
// Screen::ToString).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace accelcal::ui {

// Colours are named by role; ui/tui/term.cpp maps each to a colour pair or a monochrome
// attribute. Meaning never depends on the role alone: the text carries markers ([FAIL], ...).
enum class Role : unsigned char { kNormal, kTitle, kPrompt, kPass, kFail, kWarn, kDim };

struct Span {
  std::string text;
  Role role = Role::kNormal;
};
using Line = std::vector<Span>;

class ScreenModel {
 public:
  ScreenModel(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // Writes `text` from (row, col); whatever falls outside the grid is dropped.
  void Put(int row, int col, std::string_view text, Role role);
  // Writes the spans of `line` one after the other from (row, col).
  void PutLine(int row, int col, const Line& line);

  char CharAt(int row, int col) const { return rows_[row][col]; }
  Role RoleAt(int row, int col) const { return roles_[row][col]; }
  const std::string& Row(int row) const { return rows_[row]; }

  // The text only: rows with trailing blanks removed, each ended by '\n'.
  std::string Text() const;

  bool operator==(const ScreenModel& other) const = default;

 private:
  int width_;
  int height_;
  std::vector<std::string> rows_;
  std::vector<std::vector<Role>> roles_;
};

}  // namespace accelcal::ui

#include "tui/screen_model.h"

#include <algorithm>

namespace accelcal::ui {

ScreenModel::ScreenModel(int width, int height)
    : width_(std::max(width, 0)),
      height_(std::max(height, 0)),
      rows_(height_, std::string(width_, ' ')),
      roles_(height_, std::vector<Role>(width_, Role::kNormal)) {}

void ScreenModel::Put(int row, int col, std::string_view text, Role role) {
  if (row < 0 || row >= height_) return;
  for (char c : text) {
    if (col >= width_) return;
    if (col >= 0) {
      // Only printable ASCII reaches the terminal (curses here is not the wide-character one).
      rows_[row][col] = (c >= 32 && c < 127) ? c : '?';
      roles_[row][col] = role;
    }
    ++col;
  }
}

void ScreenModel::PutLine(int row, int col, const Line& line) {
  for (const Span& span : line) {
    Put(row, col, span.text, span.role);
    col += static_cast<int>(span.text.size());
  }
}

std::string ScreenModel::Text() const {
  std::string out;
  for (const std::string& row : rows_) {
    const size_t end = row.find_last_not_of(' ');
    if (end != std::string::npos) out.append(row, 0, end + 1);
    out += '\n';
  }
  return out;
}

}  // namespace accelcal::ui

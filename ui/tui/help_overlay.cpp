#include "tui/help_overlay.h"

#include <algorithm>
#include <string>

#include <fmt/core.h>

#include "accelcal/app/wizard/step_help.h"
#include "tui/keys.h"
#include "tui/text_util.h"

namespace accelcal::ui {
namespace {

constexpr int kKeyColumn = 11;  // "Backspace  " and the like, so the actions line up

Line KeyRow(const std::string& key, const std::string& action, int width) {
  return {{fmt::format("  {:<{}}", key, kKeyColumn), Role::kTitle},
          {Clip(" " + Asciify(action), std::max(width - kKeyColumn - 3, 1)), Role::kNormal}};
}

// The keys of this screen, as the TUI sends them.
std::vector<Line> KeyRows(const WizardView& view, int width) {
  const bool text_field = view.input.has_value();
  std::vector<Line> rows;
  for (const KeyHint& hint : view.keys) {
    const std::string key = KeyName(hint.key, text_field);
    if (key.empty()) continue;
    rows.push_back(KeyRow(key, key == "Esc" ? hint.action + " (clears an answer being typed first)"
                                            : hint.action,
                          width));
  }
  if (text_field) rows.push_back(KeyRow("Backspace", "delete the last character typed", width));
  rows.push_back(KeyRow("? or F1", "this help", width));
  if (!view.lines.empty()) rows.push_back(KeyRow("PgUp/PgDn", "scroll the text (and the arrows)", width));
  return rows;
}

}  // namespace

std::vector<Line> HelpBlock(const WizardView& view, int width) {
  std::vector<Line> rows;
  rows.push_back({{Clip("Help: what this step expects", width), Role::kTitle}});
  for (const std::string& paragraph : StepHelp(view)) {
    for (const std::string& row : Wrap(Asciify(paragraph), std::max(width - 1, 1)))
      rows.push_back({{row, Role::kNormal}});
  }
  rows.push_back({{Clip(view.input ? "Keys (letters are typed into the answer):" : "Keys:", width),
                   Role::kTitle}});
  const std::vector<Line> keys = KeyRows(view, width);
  rows.insert(rows.end(), keys.begin(), keys.end());
  return rows;
}

}  // namespace accelcal::ui

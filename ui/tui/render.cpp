#include "tui/render.h"

#include <algorithm>

#include <fmt/core.h>

#include "tui/help_overlay.h"
#include "tui/capture_blocks.h"
#include "tui/render_blocks.h"
#include "tui/text_util.h"

namespace accelcal::ui {

namespace {

// A run of rows between the header and the keys; lower `priority` gives way first when the
// terminal is short.
struct Block {
  int priority;
  std::vector<Line> lines;
};

int Rows(const std::vector<Block>& blocks) {
  int n = 0;
  for (const Block& b : blocks) n += static_cast<int>(b.lines.size());
  return n;
}

// Cuts rows from the ends of the least important blocks until `blocks` fit in `rows`.
void Shrink(std::vector<Block>& blocks, int rows) {
  int overflow = Rows(blocks) - rows;
  for (int priority = 0; overflow > 0 && priority <= 9; ++priority) {
    for (Block& b : blocks) {
      if (b.priority != priority || overflow <= 0) continue;
      const int cut = std::min(overflow, static_cast<int>(b.lines.size()));
      b.lines.resize(b.lines.size() - cut);
      overflow -= cut;
    }
  }
}

// The middle blocks in screen order. The text lines are not among them: they take what is left.
// A record's panel takes `record_rows` (what the other blocks leave).
std::vector<Block> MiddleBlocks(const WizardView& view, const RenderState& state, int width,
                                bool with_drawing, int record_rows) {
  std::vector<Line> panel;
  if (view.record) {
    panel = RecordBlock(view, width, record_rows);
  } else {
    if (with_drawing) panel = PanelWithDrawing(view);
    if (panel.empty()) panel = ReadingBlock(view);
  }
  return {
      {7, TitleBlock(view, width)},
      {9, VerdictBlock(view, width)},
      {6, NoticeBlock(view, width)},
      {5, PromptBlock(view, width)},
      {4, std::move(panel)},
      {8, ProblemBlock(view, width)},
      {6, SourceNoticeBlock(view, state, width)},
      {6, DetailBlock(view, state, width)},
      {5, TimeBlock(view, width)},
      {9, InputBlock(view, state, width)},
  };
}

// The text lines from `first` in `rows` rows; the last row says where we are when they do not
// all fit.
std::vector<Line> LinesArea(const std::vector<std::string>& lines, int first, int rows) {
  std::vector<Line> out;
  const int n = static_cast<int>(lines.size());
  if (rows <= 0 || n == 0) return out;
  const bool all_fit = n <= rows;
  const int shown = all_fit ? n : std::max(rows - 1, 1);
  first = std::clamp(first, 0, std::max(n - shown, 0));
  for (int i = first; i < first + shown && i < n; ++i) out.push_back({{Asciify(lines[i])}});
  if (!all_fit && rows > 1) {
    out.push_back({{fmt::format("-- lines {}-{} of {} (PgUp/PgDn) --", first + 1,
                                first + shown, n),
                    Role::kDim}});
  }
  return out;
}

}  // namespace

ScreenModel Render(const WizardView& view, const RenderState& state, int width, int height) {
  ScreenModel screen(width, height);
  if (width <= 0 || height <= 0) return screen;
  screen.PutLine(0, 0, HeaderLine(view, width));
  if (height == 1) return screen;
  const int middle_rows = height - 2;  // between the header and the keys
  if (state.help) {
    std::vector<Line> help = HelpBlock(view, width);
    help.resize(std::min(help.size(), static_cast<size_t>(middle_rows)));
    for (size_t i = 0; i < help.size(); ++i) screen.PutLine(static_cast<int>(i) + 1, 0, help[i]);
    screen.PutLine(height - 1, 0, {{"any key", Role::kTitle}, {" close the help", Role::kNormal}});
    return screen;
  }

  // A record's panel takes the rows the other blocks leave.
  std::vector<Block> others = MiddleBlocks(view, state, width, false, 0);
  others.push_back({3, StatusBlock(view)});
  const int record_rows = middle_rows - Rows(others);
  // The drawing only when it fits beside the reading and leaves the rest whole.
  std::vector<Block> blocks = MiddleBlocks(view, state, width, width >= 60, record_rows);
  blocks.push_back({3, StatusBlock(view)});
  if (Rows(blocks) > middle_rows) {
    blocks = MiddleBlocks(view, state, width, false, record_rows);
    blocks.push_back({3, StatusBlock(view)});
  }
  Shrink(blocks, middle_rows);
  const int free_rows = middle_rows - Rows(blocks);
  // Lines wider than the screen are wrapped, never cut at the right edge.
  const std::vector<std::string> lines = ScreenTextLines(view, width);
  const bool scrollable = static_cast<int>(lines.size()) > free_rows;
  // The status sits just above the keys; the text lines take the rows in between.
  const std::vector<Line> status = std::move(blocks.back().lines);
  blocks.pop_back();
  blocks.push_back(Block{0, LinesArea(lines, state.scroll, free_rows)});

  int row = 1;
  for (const Block& b : blocks) {
    for (const Line& line : b.lines) screen.PutLine(row++, 0, line);
  }
  row = height - 1 - static_cast<int>(status.size());
  for (const Line& line : status) screen.PutLine(row++, 0, line);
  screen.PutLine(height - 1, 0,
                 KeysLine(view, scrollable && !lines.empty(), !state.edit_text.empty(), width));
  return screen;
}

}  // namespace accelcal::ui

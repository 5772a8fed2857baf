#include "tui/capture_blocks.h"

#include <algorithm>

#include "tui/text_util.h"

namespace accelcal::ui {
namespace {

// `text` wrapped at `width`, the first row after `lead`, the others indented to match.
std::vector<Line> Led(const std::string& lead, const std::string& text, int width, Role lead_role,
                      Role role) {
  const int indent = static_cast<int>(lead.size());
  std::vector<Line> rows;
  for (const std::string& row : Wrap(Asciify(text), std::max(width - indent, 1))) {
    rows.push_back({{rows.empty() ? lead : std::string(indent, ' '), lead_role}, {row, role}});
  }
  return rows;
}

}  // namespace

std::vector<Line> NoticeBlock(const WizardView& view, int width) {
  if (view.notice.empty()) return {};
  return Led("[DONE] ", view.notice, width, Role::kPass, Role::kPass);
}

std::vector<Line> SourceNoticeBlock(const WizardView& view, const RenderState& state, int width) {
  if (view.source_notice.empty()) return {};
  std::vector<Line> rows = Led("[LINK] ", view.source_notice, width, Role::kWarn, Role::kWarn);
  if (state.details && !view.source_detail.empty()) {
    std::vector<Line> figures = Led("detail   ", view.source_detail, width, Role::kDim, Role::kDim);
    rows.insert(rows.end(), figures.begin(), figures.end());
  }
  return rows;
}

std::vector<Line> TimeBlock(const WizardView& view, int width) {
  if (view.time_text.empty()) return {};
  return Led("time     ", view.time_text, width, Role::kDim, Role::kNormal);
}

std::vector<Line> DetailBlock(const WizardView& view, const RenderState& state, int width) {
  if (view.detail.empty() || !state.details) return {};
  return Led("detail   ", view.detail, width, Role::kDim, Role::kDim);
}

std::vector<Line> VerdictBlock(const WizardView& view, int width) {
  if (view.verdict.empty()) return {};
  const Role role = view.verdict == "PASS" ? Role::kPass : view.verdict == "FAIL" ? Role::kFail : Role::kWarn;
  const std::string mark = view.verdict == "PASS" ? "[PASS] " : view.verdict == "FAIL" ? "[FAIL] " : "[ -- ] ";
  return Led(mark, "Verdict: " + view.verdict, width, role, role);
}

std::vector<std::string> ScreenTextLines(const WizardView& view, int width) {
  std::vector<std::string> lines = view.lines;
  if (!view.verdict.empty() && !lines.empty() && lines.front() == "Verdict: " + view.verdict)
    lines.erase(lines.begin());
  return WrapLines(lines, width);
}

}  // namespace accelcal::ui

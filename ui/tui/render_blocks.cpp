#include "tui/render_blocks.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "accelcal/base/duration_text.h"
#include "tui/gauge.h"
#include "tui/keys.h"
#include "tui/prism_drawing.h"
#include "tui/record_plot.h"
#include "tui/text_util.h"

namespace accelcal::ui {

namespace {

// "refit (recommended)" -> "refit": a key bar's action without its remarks in brackets.
std::string WithoutRemarks(const std::string& action) {
  std::string out;
  int depth = 0;
  for (char c : action) {
    if (c == '(') ++depth;
    if (depth == 0) out += c;
    if (c == ')' && depth > 0) --depth;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

constexpr int kBarCells = 16;
constexpr int kLabelWidth = 9;  // "stable   " and the like, so the values line up

// `text` wrapped at `width`, the first line after `first`, the others indented to match.
std::vector<Line> Marked(const std::string& first, const std::string& text, int width,
                         Role role) {
  const int indent = static_cast<int>(first.size());
  std::vector<Line> lines;
  for (const std::string& row : Wrap(Asciify(text), std::max(width - indent, 1))) {
    const std::string lead = lines.empty() ? first : std::string(indent, ' ');
    lines.push_back({{lead + row, role}});
  }
  return lines;
}

Line Labelled(const std::string& label, const std::string& value, Role role = Role::kNormal) {
  return {{fmt::format("{:<{}}", label, kLabelWidth), Role::kDim}, {value, role}};
}

bool WantsReading(const WizardView& view) {
  switch (view.screen) {
    case WizardScreen::kLevel:
    case WizardScreen::kPlacePose:
    case WizardScreen::kMountTurntable:
    case WizardScreen::kCapturing:
      return true;
    case WizardScreen::kFit:
    case WizardScreen::kDiagnosis:
    case WizardScreen::kReport:
    case WizardScreen::kDone:
      return false;  // the text lines need the room; the reading means nothing there
    default:
      return view.live_counts.array().isFinite().any();
  }
}

// The marker comes first so that a narrow terminal still shows the verdict.
Line StabilityLine(const WizardView& view) {
  const double s = view.stability;
  const std::string gauge = " " + Bar(s, kBarCells) + " " + FormatNumber(s, 2, 4);
  if (std::isnan(s)) return Labelled("stable", "[ -- ]" + gauge, Role::kDim);
  const bool still = s < 1.0;
  // Settling after the hand let go is a wait, not a warning.
  if (!still && view.waiting) return Labelled("stable", "[WAIT]" + gauge, Role::kPrompt);
  return Labelled("stable", (still ? "[ OK ]" : "[WARN]") + gauge,
                  still ? Role::kPass : Role::kWarn);
}

bool IsTurntable(const WizardView& view) {
  return view.screen == WizardScreen::kMountTurntable ||
         view.pose_name.find("radial") != std::string::npos;
}

}  // namespace

Line HeaderLine(const WizardView& view, int width) {
  std::string text = fmt::format(" Step {} of {}", view.step_index, view.step_count);
  if (!view.session.empty()) text += " | session " + view.session;
  if (!view.procedure.empty()) text += " | " + view.procedure;
  if (view.resumed) text += " | resumed";
  text = Asciify(text);
  text.resize(static_cast<size_t>(std::max(width, 0)), ' ');  // a full-width title bar
  return {{text, Role::kTitle}};
}

std::vector<Line> TitleBlock(const WizardView& view, int width) {
  if (view.step_title.empty()) return {};
  return {{{Clip(Asciify(view.step_title), width), Role::kTitle}}};
}

std::vector<Line> PromptBlock(const WizardView& view, int width) {
  return Marked("", view.prompt, width, Role::kPrompt);
}

std::vector<Line> ReadingBlock(const WizardView& view) {
  if (!WantsReading(view)) return {};
  const Eigen::Vector3d& c = view.live_counts;
  std::vector<Line> rows;
  rows.push_back(Labelled("counts", fmt::format("x {}  y {}  z {}", FormatNumber(c.x(), 0, 6),
                                                FormatNumber(c.y(), 0, 6),
                                                FormatNumber(c.z(), 0, 6))));
  rows.push_back(Labelled("|f|", FormatNumber(view.live_g, 3, 6) + " g (approx.)"));
  if (view.tilt_deg.array().isFinite().any()) {
    rows.push_back(Labelled("tilt", fmt::format("x {} deg  y {} deg",
                                                FormatNumber(view.tilt_deg.x(), 2, 6),
                                                FormatNumber(view.tilt_deg.y(), 2, 6))));
    if (!view.tilt_note.empty()) rows.push_back(Labelled("", Asciify(view.tilt_note), Role::kDim));
  }
  rows.push_back(StabilityLine(view));
  if (!view.stability_text.empty()) {
    rows.push_back(Labelled("", Asciify(view.stability_text), Role::kDim));
  }
  if (!view.noise_floor_text.empty()) {
    rows.push_back(Labelled("noise", Asciify(view.noise_floor_text), Role::kDim));
  }
  if (view.screen == WizardScreen::kCapturing || !std::isnan(view.progress)) {
    const double p = view.progress;
    rows.push_back(Labelled("capture", "       " + Bar(std::min(p, 0.999), kBarCells) + " " +
                                           FormatNumber(p * 100.0, 0, 4) + " %",
                            Role::kPrompt));
  }
  return rows;
}

std::vector<Line> PanelWithDrawing(const WizardView& view) {
  const std::vector<std::string> drawing =
      DrawPose(view.expected_up, view.pose_name, IsTurntable(view));
  if (drawing.empty()) return {};
  std::vector<Line> reading = ReadingBlock(view);
  std::vector<Line> rows;
  const size_t n = std::max(drawing.size(), reading.size());
  for (size_t i = 0; i < n; ++i) {
    const std::string left = i < drawing.size() ? drawing[i] : "";
    Line line{{fmt::format("{:<{}}", left, kDrawingWidth + 1), Role::kNormal}};
    if (i < reading.size()) line.insert(line.end(), reading[i].begin(), reading[i].end());
    rows.push_back(std::move(line));
  }
  return rows;
}

std::vector<Line> RecordBlock(const WizardView& view, int width, int rows) {
  if (!view.record || rows <= 0) return {};
  const RecordView& r = *view.record;
  std::vector<Line> out;
  const double p = r.duration_s > 0.0 ? std::clamp(r.elapsed_s / r.duration_s, 0.0, 1.0) : kNaN;
  out.push_back(Labelled("elapsed", Clip(fmt::format("{} of {} {} {} %, {} to go",
                                                     FormatClock(r.elapsed_s), FormatClock(r.duration_s),
                                                     Bar(std::min(p, 0.999), kBarCells),
                                                     FormatNumber(p * 100.0, 0, 3),
                                                     FormatClock(r.duration_s - r.elapsed_s)),
                                         std::max(width - kLabelWidth, 1)),
                         Role::kPrompt));
  out.push_back(Labelled("recorded",
                         Clip(fmt::format("{} in {} chunks, {} samples; gaps {} ({})",
                                          FormatLongDuration(r.recorded_s), r.chunks, r.samples,
                                          r.gaps, FormatLongDuration(r.gaps_s)),
                              std::max(width - kLabelWidth, 1))));
  out.push_back(r.bumps == 0
                    ? Labelled("movement", "[ OK ] none", Role::kPass)
                    : Labelled("movement", Clip("[WARN] " + Asciify(view.stability_text),
                                                std::max(width - kLabelWidth, 1)),
                               Role::kWarn));
  const Eigen::Vector3d& c = view.live_counts;
  out.push_back(Labelled("counts", fmt::format("x {}  y {}  z {}", FormatNumber(c.x(), 0, 6),
                                               FormatNumber(c.y(), 0, 6), FormatNumber(c.z(), 0, 6))));
  const bool allan_data = std::any_of(r.allan.begin(), r.allan.end(),
                                      [](const std::vector<AllanCurvePoint>& a) { return !a.empty(); });
  const int allan_rows = allan_data ? std::clamp(rows / 4, 3, 9) : 1;
  const int fixed = static_cast<int>(out.size()) + 1 + allan_rows;  // + the drift heading
  const int per_axis = std::clamp((rows - fixed) / 3, 0, 6);
  if (per_axis > 0) {
    out.push_back({{Clip(fmt::format("drift, counts vs the first minute ({} per point):",
                                     FormatLongDuration(r.drift_bin_s)),
                         width),
                    Role::kDim}});
    for (int axis = 0; axis < 3; ++axis)
      for (const std::string& row : DriftPlot(r, axis, width, per_axis)) out.push_back({{row}});
  }
  for (const std::string& row : AllanPlot(r, width, allan_rows))
    out.push_back({{Clip(row, width), allan_data ? Role::kNormal : Role::kDim}});
  return out;
}

std::vector<Line> ProblemBlock(const WizardView& view, int width) {
  std::vector<Line> rows;
  if (!view.problem.empty()) rows = Marked("[FAIL] ", view.problem, width, Role::kFail);
  if (!view.hint.empty()) {
    std::vector<Line> hint = Marked("[HINT] ", view.hint, width, Role::kWarn);
    rows.insert(rows.end(), hint.begin(), hint.end());
  }
  return rows;
}

std::vector<Line> InputBlock(const WizardView& view, const RenderState& state, int width) {
  if (!view.input) return {};
  const InputRequest& in = *view.input;
  std::vector<Line> rows = Marked("> ", in.label, width, Role::kPrompt);
  std::string answer = "  answer";
  if (!in.default_text.empty()) answer += " [" + Asciify(in.default_text) + "]";
  answer += ": ";
  // Show the end of a long answer so the cursor mark stays in view.
  const int room = std::max(width - static_cast<int>(answer.size()) - 1, 1);
  std::string typed = Asciify(state.edit_text);
  if (static_cast<int>(typed.size()) > room) typed = typed.substr(typed.size() - room);
  rows.push_back({{answer, Role::kPrompt}, {typed + "_", Role::kNormal}});
  if (!in.error.empty()) {
    std::vector<Line> error = Marked("[FAIL] ", in.error, width, Role::kFail);
    rows.insert(rows.end(), error.begin(), error.end());
  }
  return rows;
}

std::vector<Line> StatusBlock(const WizardView& view) {
  if (view.status.empty()) return {};
  return {{{Asciify(view.status), Role::kDim}}};
}

Line KeysLine(const WizardView& view, bool scrollable, bool typed, int width) {
  std::vector<std::pair<std::string, std::string>> entries;  // key, action
  auto add = [&entries](const std::string& key, const std::string& action) {
    entries.emplace_back(Asciify(key), Asciify(action));
  };
  if (view.finished) {
    add("any key", "leave");
  } else {
    // q and ? work at any moment (help names every other key); they come first so that a
    // narrow terminal still shows them.
    const bool text_field = view.input.has_value();
    std::string quit_action = "save and quit";
    for (const KeyHint& hint : view.keys) {
      if (hint.key == "q") quit_action = hint.action;
    }
    add(KeyName("q", text_field), quit_action);
    add("?", "help");
    for (const KeyHint& hint : view.keys) {
      if (hint.key == "q") continue;
      const std::string key = KeyName(hint.key, text_field);
      if (key.empty()) continue;  // a letter: it would be typed, not obeyed
      add(key, key == "Esc" && typed ? "clear" : hint.action);
    }
  }
  if (!view.finished && (!view.detail.empty() || !view.source_detail.empty())) add("d", "figures");
  if (scrollable) add("PgUp/PgDn", "scroll");
  // Too wide: the actions lose their remarks in brackets first ("refit (recommended)": the
  // question says it), then the last entries are left off whole, never cut in a word.
  auto width_of = [](const std::vector<std::pair<std::string, std::string>>& all) {
    int total = 0;
    for (const auto& [key, action] : all) total += (total == 0 ? 0 : 2) + static_cast<int>(key.size() + 1 + action.size());
    return total;
  };
  if (width > 0 && width_of(entries) > width)
    for (auto& entry : entries) entry.second = WithoutRemarks(entry.second);
  Line line;
  int used = 0;
  for (const auto& [key, action] : entries) {
    const int cost = (line.empty() ? 0 : 2) + static_cast<int>(key.size() + 1 + action.size());
    if (width > 0 && used + cost > width && !line.empty()) break;
    if (!line.empty()) line.push_back({"  ", Role::kNormal});
    line.push_back({key, Role::kTitle});
    line.push_back({" " + action, Role::kNormal});
    used += cost;
  }
  return line;
}

}  // namespace accelcal::ui

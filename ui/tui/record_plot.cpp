#include "tui/record_plot.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace accelcal::ui {
namespace {

constexpr int kSubLevels = 3;
// The drift plot's value range is never narrower than this (noise of a fraction of a count
// would otherwise fill the height), counts.
constexpr double kMinRangeCounts = 1.0;
constexpr char kLevelGlyph[kSubLevels] = {'.', '-', '\''};

// A blank canvas of `rows` x `width` with a label column and a '|' axis.
std::vector<std::string> Canvas(int width, int rows) {
  std::vector<std::string> out(static_cast<size_t>(rows), std::string(static_cast<size_t>(width), ' '));
  for (std::string& row : out)
    if (width > kPlotLabelWidth) row[kPlotLabelWidth - 1] = '|';
  return out;
}

void Label(std::string& row, const std::string& text) {
  const std::string clipped = text.substr(0, static_cast<size_t>(kPlotLabelWidth - 2));
  row.replace(0, clipped.size(), clipped);
}

// Puts `glyph` at value `v` of [lo, hi] (hi at the top) in column `col`.
void Plot(std::vector<std::string>& canvas, int col, double v, double lo, double hi, char glyph) {
  const int rows = static_cast<int>(canvas.size());
  const int levels = rows * kSubLevels;
  const double f = hi > lo ? (v - lo) / (hi - lo) : 0.5;
  const int level = std::clamp(static_cast<int>(std::floor(f * levels)), 0, levels - 1);
  const int row = rows - 1 - level / kSubLevels;
  char& cell = canvas[static_cast<size_t>(row)][static_cast<size_t>(col)];
  if (glyph == 0) {
    cell = kLevelGlyph[level % kSubLevels];
  } else {
    cell = (cell == ' ' || cell == glyph) ? glyph : '*';
  }
}

}  // namespace

std::vector<std::string> DriftPlot(const RecordView& record, int axis, int width, int rows) {
  if (rows <= 0 || width <= kPlotLabelWidth + 1) return {};
  std::vector<std::string> canvas = Canvas(width, rows);
  const int cols = width - kPlotLabelWidth;
  double lo = INFINITY, hi = -INFINITY;
  for (const DriftPoint& p : record.drift) {
    lo = std::min(lo, p.drift_counts(axis));
    hi = std::max(hi, p.drift_counts(axis));
  }
  if (!(hi - lo >= kMinRangeCounts)) {
    const double mid = std::isfinite(lo) ? 0.5 * (lo + hi) : 0.0;
    lo = mid - 0.5 * kMinRangeCounts;
    hi = mid + 0.5 * kMinRangeCounts;
  }
  Label(canvas.front(), fmt::format("{}{:+.1f}", "xyz"[axis], hi));
  if (rows > 1) Label(canvas.back(), fmt::format(" {:+.1f}", lo));
  const double span_s = std::max(record.duration_s, 1e-9);
  for (const DriftPoint& p : record.drift) {
    const int col = std::clamp(static_cast<int>(p.t_s / span_s * cols), 0, cols - 1);
    Plot(canvas, kPlotLabelWidth + col, p.drift_counts(axis), lo, hi, 0);
  }
  return canvas;
}

std::vector<std::string> AllanPlot(const RecordView& record, int width, int rows) {
  double tau_lo = INFINITY, tau_hi = -INFINITY, a_lo = INFINITY, a_hi = -INFINITY;
  for (const std::vector<AllanCurvePoint>& curve : record.allan) {
    for (const AllanCurvePoint& p : curve) {
      if (!(p.tau_s > 0.0) || !(p.adev_counts > 0.0)) continue;
      tau_lo = std::min(tau_lo, std::log10(p.tau_s));
      tau_hi = std::max(tau_hi, std::log10(p.tau_s));
      a_lo = std::min(a_lo, std::log10(p.adev_counts));
      a_hi = std::max(a_hi, std::log10(p.adev_counts));
    }
  }
  if (!std::isfinite(tau_lo) || rows < 3 || width <= kPlotLabelWidth + 1)
    return {std::isfinite(tau_lo) ? "Allan curve: no room to draw it" : "Allan curve: waiting for data"};
  std::vector<std::string> out = {fmt::format(
      "Allan deviation, counts (log) vs tau {:.3g} .. {:.3g} s (log): x y z", std::pow(10.0, tau_lo),
      std::pow(10.0, tau_hi))};
  std::vector<std::string> canvas = Canvas(width, rows - 1);
  Label(canvas.front(), fmt::format("{:.2g}", std::pow(10.0, a_hi)));
  Label(canvas.back(), fmt::format("{:.2g}", std::pow(10.0, a_lo)));
  const int cols = width - kPlotLabelWidth;
  for (int axis = 0; axis < 3; ++axis) {
    for (const AllanCurvePoint& p : record.allan[static_cast<size_t>(axis)]) {
      if (!(p.tau_s > 0.0) || !(p.adev_counts > 0.0)) continue;
      const double f = tau_hi > tau_lo ? (std::log10(p.tau_s) - tau_lo) / (tau_hi - tau_lo) : 0.5;
      const int col = std::clamp(static_cast<int>(f * (cols - 1) + 0.5), 0, cols - 1);
      Plot(canvas, kPlotLabelWidth + col, std::log10(p.adev_counts), a_lo, a_hi, "xyz"[axis]);
    }
  }
  out.insert(out.end(), canvas.begin(), canvas.end());
  return out;
}

}  // namespace accelcal::ui

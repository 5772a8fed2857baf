// A small plotter that writes an inline SVG element (for the HTML report): a frame with ticks,
// tick labels and axis titles, linear or log10 axes, series drawn as lines and/or markers, a
// shaded band between two curves (a confidence interval), labelled point marks (read-offs),
// and a legend. No scripts, no external references: the SVG stands alone in a page.
//
// Output is deterministic: coordinates are printed with two decimals, tick values with the
// shortest "%g"-style text of a 1-2-5 step (linear) or a power of ten (log), so the same data
// always gives byte-identical SVG.
//
// Non-finite points are skipped (a line is broken there); on a log axis so are points <= 0.
#pragma once

#include <string>
#include <vector>

namespace accelcal {

// Escapes & < > " ' for HTML/XML text and attribute values.
std::string EscapeXml(const std::string& text);

struct SvgSeries {
  std::string name;            // in the legend; empty: not listed
  std::vector<double> x, y;    // same length
  std::string color = "#1f4e79";
  bool line = true;
  bool markers = false;
  enum class Marker { kCircle, kSquare, kDiamond } marker = Marker::kCircle;
  bool dashed = false;
  // When both are non-empty (same length as x): a shaded band from band_lo to band_hi.
  std::vector<double> band_lo, band_hi;
};

// A labelled point (e.g. "B = 0.012 at 40 s").
struct SvgMark {
  double x = 0.0, y = 0.0;
  std::string text;
  std::string color = "#b22222";
  double label_dy_px = -8.0;  // the label's baseline relative to the point (negative: above)
};

struct SvgPlotOptions {
  std::string title;
  std::string x_label, y_label;
  int width_px = 900;
  int height_px = 300;
  bool log_x = false;
  bool log_y = false;
  bool zero_line = false;       // a horizontal rule at y = 0 (residual plots)
  bool integer_x_ticks = false; // ticks only at whole numbers (capture ids)
};

class SvgPlot {
 public:
  explicit SvgPlot(SvgPlotOptions options) : options_(std::move(options)) {}
  void Add(SvgSeries series) { series_.push_back(std::move(series)); }
  void Mark(SvgMark mark) { marks_.push_back(std::move(mark)); }
  // The <svg> element. With no finite point at all, a frame that says "no data".
  std::string Render() const;

 private:
  SvgPlotOptions options_;
  std::vector<SvgSeries> series_;
  std::vector<SvgMark> marks_;
};

// Tick values for [lo, hi]: a 1-2-5 step giving about `target` ticks (linear), or the powers
// of ten inside the range (log; at least the two around it). Exposed for tests.
std::vector<double> LinearTicks(double lo, double hi, int target);

// Points that would draw on top of each other, spread sideways so each shows: the x of the
// points within `width` of each other (in x's unit, after sorting) are set apart by `width`,
// centred on their mean. Returns how many points were moved. y is untouched.
int SpreadCoincident(std::vector<double>* x, double width);
std::vector<double> LogTicks(double lo, double hi);
// A tick label: "0.05", "1e-03" style for small/large magnitudes, "-2", "120".
std::string TickLabel(double v);

}  // namespace accelcal

#include "accelcal/report/svg_plot.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

// Plot area inside the SVG, px.
constexpr double kLeft = 74, kRight = 18, kTop = 52, kBottom = 46;
constexpr double kCharWidthPx = 6.6;  // approximate advance of the 12 px sans-serif legend font

struct Range {
  double lo = INFINITY, hi = -INFINITY;
  void Add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool Valid() const { return lo <= hi; }
};

double NiceStep(double raw) {
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / mag;
  const double nice = r <= 1.0 ? 1.0 : r <= 2.0 ? 2.0 : r <= 5.0 ? 5.0 : 10.0;
  return nice * mag;
}

std::string Coord(double v) { return fmt::format("{:.2f}", v); }

// One axis: data value -> pixel.
struct Axis {
  double lo = 0, hi = 1;     // in data units (log: log10 of them)
  bool log = false;
  double px0 = 0, px1 = 1;   // pixel of lo and hi
  std::vector<double> ticks; // data units

  double Map(double v) const {
    const double u = log ? std::log10(v) : v;
    return px0 + (u - lo) / (hi - lo) * (px1 - px0);
  }
  bool Usable(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
};

Axis MakeAxis(Range r, bool log, bool integer_ticks, double px0, double px1) {
  Axis a;
  a.log = log;
  a.px0 = px0;
  a.px1 = px1;
  if (!r.Valid()) r = log ? Range{1.0, 10.0} : Range{0.0, 1.0};
  if (log) {
    a.lo = std::floor(std::log10(r.lo));
    a.hi = std::ceil(std::log10(r.hi));
    if (a.hi <= a.lo) a.hi = a.lo + 1;
    a.ticks = LogTicks(r.lo, r.hi);
    return a;
  }
  if (r.hi - r.lo < 1e-12 * std::max(1.0, std::abs(r.hi))) {
    const double pad = r.lo == 0.0 ? 1.0 : std::abs(r.lo) * 0.1;
    r.lo -= pad;
    r.hi += pad;
  }
  double step = NiceStep((r.hi - r.lo) / 5.0);
  if (integer_ticks) step = std::max(1.0, std::round(step));
  a.lo = std::floor(r.lo / step) * step;
  a.hi = std::ceil(r.hi / step) * step;
  if (integer_ticks) {
    a.lo -= 0.5;  // room for the first and last marker
    a.hi += 0.5;
  }
  for (double t = std::ceil(a.lo / step) * step; t <= a.hi + step * 1e-9; t += step)
    a.ticks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  return a;
}

std::string MarkerSvg(SvgSeries::Marker m, double x, double y, const std::string& color) {
  switch (m) {
    case SvgSeries::Marker::kSquare:
      return fmt::format("<rect x=\"{}\" y=\"{}\" width=\"7\" height=\"7\" fill=\"{}\"/>", Coord(x - 3.5),
                         Coord(y - 3.5), color);
    case SvgSeries::Marker::kDiamond:
      return fmt::format("<path d=\"M{} {}l4 4l-4 4l-4 -4z\" fill=\"{}\"/>", Coord(x), Coord(y - 4), color);
    case SvgSeries::Marker::kCircle: break;
  }
  return fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"3.5\" fill=\"{}\"/>", Coord(x), Coord(y), color);
}

std::string Band(const SvgSeries& s, const Axis& ax, const Axis& ay) {
  if (s.band_lo.size() != s.x.size() || s.band_hi.size() != s.x.size()) return "";
  std::string fwd, back;
  for (size_t i = 0; i < s.x.size(); ++i) {
    if (!ax.Usable(s.x[i]) || !ay.Usable(s.band_lo[i]) || !ay.Usable(s.band_hi[i])) continue;
    fwd += fmt::format("{}{} {} ", fwd.empty() ? "M" : "L", Coord(ax.Map(s.x[i])), Coord(ay.Map(s.band_hi[i])));
    back = fmt::format("L{} {} ", Coord(ax.Map(s.x[i])), Coord(ay.Map(s.band_lo[i]))) + back;
  }
  if (fwd.empty()) return "";
  return fmt::format("<path d=\"{}{}Z\" fill=\"{}\" fill-opacity=\"0.18\" stroke=\"none\"/>\n", fwd, back, s.color);
}

std::string Lines(const SvgSeries& s, const Axis& ax, const Axis& ay) {
  std::string out, points;
  auto flush = [&] {
    if (points.find(' ') != points.rfind(' '))  // at least two points
      out += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.6\"{}/>\n",
                         points.substr(0, points.size() - 1), s.color,
                         s.dashed ? " stroke-dasharray=\"5 3\"" : "");
    points.clear();
  };
  for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!ax.Usable(s.x[i]) || !ay.Usable(s.y[i])) {
      flush();
      continue;
    }
    points += Coord(ax.Map(s.x[i])) + "," + Coord(ay.Map(s.y[i])) + " ";
  }
  flush();
  return out;
}

std::string Legend(const std::vector<SvgSeries>& series, double width) {
  std::string out;
  double x = kLeft;
  for (const SvgSeries& s : series) {
    if (s.name.empty()) continue;
    const double w = 30 + kCharWidthPx * static_cast<double>(s.name.size()) + 16;
    if (x + w > width && x > kLeft) break;  // no room: the rest stays unlisted rather than overlapping
    const double y = 38;
    if (!s.band_lo.empty())
      out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"22\" height=\"10\" fill=\"{}\" fill-opacity=\"0.18\"/>",
                         Coord(x), Coord(y - 5), s.color);
    if (s.line)
      out += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"1.6\"{}/>",
                         Coord(x), Coord(y), Coord(x + 22), Coord(y), s.color,
                         s.dashed ? " stroke-dasharray=\"5 3\"" : "");
    if (s.markers) out += MarkerSvg(s.marker, x + 11, y, s.color);
    out += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"12\">{}</text>\n", Coord(x + 28), Coord(y + 4),
                       EscapeXml(s.name));
    x += w;
  }
  return out;
}

}  // namespace

std::string EscapeXml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::vector<double> LinearTicks(double lo, double hi, int target) {
  std::vector<double> out;
  if (!(hi > lo) || target < 1) return out;
  const double step = NiceStep((hi - lo) / target);
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step)
    out.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  return out;
}

std::vector<double> LogTicks(double lo, double hi) {
  std::vector<double> out;
  if (!(lo > 0.0) || !(hi >= lo)) return out;
  int a = static_cast<int>(std::floor(std::log10(lo)));
  int b = static_cast<int>(std::ceil(std::log10(hi)));
  if (b <= a) b = a + 1;
  for (int k = a; k <= b; ++k) out.push_back(std::pow(10.0, k));
  return out;
}

std::string TickLabel(double v) {
  if (v == 0.0) return "0";
  const double a = std::abs(v);
  if (a >= 1e5 || a < 1e-3) return fmt::format("{:.0e}", v);
  return fmt::format("{:.6g}", v);
}

std::string SvgPlot::Render() const {
  const double w = options_.width_px, h = options_.height_px;
  Range rx, ry;
  for (const SvgSeries& s : series_) {
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.y[i]) || (options_.log_y && s.y[i] <= 0)) continue;
      if (!std::isfinite(s.x[i]) || (options_.log_x && s.x[i] <= 0)) continue;
      rx.Add(s.x[i]);
      ry.Add(s.y[i]);
      if (i < s.band_lo.size() && (!options_.log_y || s.band_lo[i] > 0)) ry.Add(s.band_lo[i]);
      if (i < s.band_hi.size()) ry.Add(s.band_hi[i]);
    }
  }
  if (options_.zero_line && ry.Valid()) ry.Add(0.0);
  const bool has_data = rx.Valid() && ry.Valid();
  const Axis ax = MakeAxis(rx, options_.log_x, options_.integer_x_ticks, kLeft, w - kRight);
  const Axis ay = MakeAxis(ry, options_.log_y, false, h - kBottom, kTop);

  std::string out = fmt::format(
      "<svg class=\"plot\" viewBox=\"0 0 {} {}\" width=\"{}\" height=\"{}\" role=\"img\" "
      "aria-label=\"{}\" font-family=\"Helvetica, Arial, sans-serif\">\n",
      w, h, w, h, EscapeXml(options_.title));
  out += fmt::format("<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>\n", w, h);
  out += fmt::format("<text x=\"{}\" y=\"18\" font-size=\"14\" font-weight=\"bold\">{}</text>\n", Coord(kLeft),
                     EscapeXml(options_.title));
  // Grid and ticks.
  for (double t : ax.ticks) {
    const double px = ax.Map(t);
    if (px < kLeft - 0.5 || px > w - kRight + 0.5) continue;
    out += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#e3e3e3\"/>"
                       "<line x1=\"{0}\" y1=\"{2}\" x2=\"{0}\" y2=\"{3}\" stroke=\"#333\"/>"
                       "<text x=\"{0}\" y=\"{4}\" font-size=\"11\" text-anchor=\"middle\">{5}</text>\n",
                       Coord(px), Coord(kTop), Coord(h - kBottom), Coord(h - kBottom + 5),
                       Coord(h - kBottom + 18), EscapeXml(TickLabel(t)));
  }
  for (double t : ay.ticks) {
    const double py = ay.Map(t);
    if (py < kTop - 0.5 || py > h - kBottom + 0.5) continue;
    out += fmt::format("<line x1=\"{1}\" y1=\"{0}\" x2=\"{2}\" y2=\"{0}\" stroke=\"#e3e3e3\"/>"
                       "<line x1=\"{3}\" y1=\"{0}\" x2=\"{1}\" y2=\"{0}\" stroke=\"#333\"/>"
                       "<text x=\"{4}\" y=\"{5}\" font-size=\"11\" text-anchor=\"end\">{6}</text>\n",
                       Coord(py), Coord(kLeft), Coord(w - kRight), Coord(kLeft - 5), Coord(kLeft - 8),
                       Coord(py + 4), EscapeXml(TickLabel(t)));
  }
  if (options_.zero_line && has_data && !options_.log_y)
    out += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#555\" stroke-dasharray=\"2 2\"/>\n",
                       Coord(kLeft), Coord(ay.Map(0.0)), Coord(w - kRight), Coord(ay.Map(0.0)));
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333\"/>\n",
                     Coord(kLeft), Coord(kTop), Coord(w - kLeft - kRight), Coord(h - kTop - kBottom));
  out += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\">{}</text>\n",
                     Coord((kLeft + w - kRight) / 2), Coord(h - 8), EscapeXml(options_.x_label));
  out += fmt::format("<text x=\"14\" y=\"{0}\" font-size=\"12\" text-anchor=\"middle\" "
                     "transform=\"rotate(-90 14 {0})\">{1}</text>\n",
                     Coord((kTop + h - kBottom) / 2), EscapeXml(options_.y_label));
  if (!has_data) {
    out += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"13\" text-anchor=\"middle\">no data</text>\n",
                       Coord(w / 2), Coord(h / 2));
    return out + "</svg>\n";
  }
  for (const SvgSeries& s : series_) out += Band(s, ax, ay);
  for (const SvgSeries& s : series_) {
    if (s.line) out += Lines(s, ax, ay);
    if (!s.markers) continue;
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (ax.Usable(s.x[i]) && ay.Usable(s.y[i]))
        out += MarkerSvg(s.marker, ax.Map(s.x[i]), ay.Map(s.y[i]), s.color);
    out += "\n";
  }
  for (const SvgMark& m : marks_) {
    if (!ax.Usable(m.x) || !ay.Usable(m.y)) continue;
    const double px = ax.Map(m.x), py = ay.Map(m.y);
    const bool right_half = px > (kLeft + w - kRight) / 2;
    out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"5\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"/>"
                       "<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"{}\" text-anchor=\"{}\">{}</text>\n",
                       Coord(px), Coord(py), m.color, Coord(right_half ? px - 9 : px + 9), Coord(py + m.label_dy_px),
                       m.color, right_half ? "end" : "start", EscapeXml(m.text));
  }
  out += Legend(series_, w);
  return out + "</svg>\n";
}

int SpreadCoincident(std::vector<double>* x, double width) {
  std::vector<size_t> order(x->size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return (*x)[a] < (*x)[b]; });
  int moved = 0;
  for (size_t begin = 0; begin < order.size();) {
    size_t end = begin + 1;
    while (end < order.size() && (*x)[order[end]] - (*x)[order[end - 1]] < width) ++end;
    const size_t n = end - begin;
    if (n > 1) {
      double mean = 0.0;
      for (size_t k = begin; k < end; ++k) mean += (*x)[order[k]];
      mean /= static_cast<double>(n);
      for (size_t k = begin; k < end; ++k)
        (*x)[order[k]] = mean + (static_cast<double>(k - begin) - 0.5 * static_cast<double>(n - 1)) * width;
      moved += static_cast<int>(n);
    }
    begin = end;
  }
  return moved;
}

}  // namespace accelcal

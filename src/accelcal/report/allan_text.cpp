#include "accelcal/report/allan_text.h"

#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

std::string Figure(double value) { return std::isfinite(value) ? fmt::format("{:.4g}", value) : "-"; }

std::string Duration(double s) {
  if (!std::isfinite(s)) return "-";
  const long total = std::lround(s);
  return fmt::format("{}h {:02}m {:02}s", total / 3600, (total / 60) % 60, total % 60);
}

// A read-off, or NaN when the curve is too short for read-offs.
double ReadOff(const AxisAnalysis& a, double AllanReadOffs::*figure) {
  return a.read_offs ? (*a.read_offs).*figure : kNaN;
}

}  // namespace

std::string FormatAllanText(const RecordAnalysis& r, const std::string& source) {
  const std::string& unit = r.unit;
  std::string out = fmt::format(
      "Allan deviation of {}\n{} samples at {} Hz{}, {}; {} missing in {} gaps\n"
      "Figures in {} (IEEE Std 952-1997 read-offs)\n\n",
      source, r.samples, Figure(r.rate_hz), r.rate_estimated ? " (from the time stamps)" : "",
      Duration(r.t_last_s - r.t_first_s), r.missing_samples, r.gaps.size(), unit);
  out += fmt::format("{:<5}{:>14}  {:>22}  {:>14}  {:>14}\n", "axis", "noise density",
                     "bias instability", "random walk", "max drift");
  out += fmt::format("{:<5}{:>14}  {:>22}  {:>14}  {:>14}\n", "", unit + "/rtHz", unit + " (at tau)",
                     unit + "/rts", unit + " (1 min)");
  double temp_min = kNaN, temp_max = kNaN;
  for (size_t i = 0; i < 3; ++i) {
    const AxisAnalysis& x = r.axes[i];
    const double tau = ReadOff(x, &AllanReadOffs::bias_instability_tau_s);
    const std::string at = std::isfinite(tau) ? fmt::format(" ({:.3g} s)", tau) : "";
    const bool rw_observed = x.read_offs && x.read_offs->random_walk_observed;
    out += fmt::format("{:<5}{:>14}  {:>22}  {:>14}  {:>14}\n", "xyz"[i],
                       Figure(ReadOff(x, &AllanReadOffs::noise_density)),
                       Figure(ReadOff(x, &AllanReadOffs::bias_instability)) + at,
                       Figure(ReadOff(x, &AllanReadOffs::random_walk)) + (rw_observed ? "" : "*"),
                       Figure(x.drift.max_drift));
    if (!std::isnan(x.drift.temp_min_c))
      temp_min = std::isnan(temp_min) ? x.drift.temp_min_c : std::min(temp_min, x.drift.temp_min_c);
    if (!std::isnan(x.drift.temp_max_c))
      temp_max = std::isnan(temp_max) ? x.drift.temp_max_c : std::max(temp_max, x.drift.temp_max_c);
  }
  out += "  * not observed in this record: an upper bound\n";
  if (!std::isnan(temp_min)) {
    out += fmt::format("\nTemperature {:.2f} .. {:.2f} degC; correlation of the 1-minute means:",
                       temp_min, temp_max);
    for (size_t i = 0; i < 3; ++i) out += fmt::format(" {} {}", "xyz"[i], Figure(r.axes[i].drift.temp_correlation));
    out += "\n";
  }
  bool header = false;
  for (size_t i = 0; i < 3; ++i) {
    const AxisAnalysis& x = r.axes[i];
    std::vector<std::string> notes;
    if (x.read_offs) notes = x.read_offs->notes;
    else notes.push_back("too short for read-offs: fewer than 3 averaging times");
    for (const std::string& note : notes) {
      if (!header) out += "\nNotes:\n";
      header = true;
      out += fmt::format("  {}: {}\n", "xyz"[i], note);
    }
  }
  return out;
}

}  // namespace accelcal

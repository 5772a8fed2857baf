#include "accelcal/report/allan_text.h"

#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

using nlohmann::json;

std::string Figure(const json& value) {
  return value.is_number() ? fmt::format("{:.4g}", value.get<double>()) : "-";
}

std::string Duration(double s) {
  if (!std::isfinite(s)) return "-";
  const long total = std::lround(s);
  return fmt::format("{}h {:02}m {:02}s", total / 3600, (total / 60) % 60, total % 60);
}

}  // namespace

std::string FormatAllanText(const json& a) {
  const std::string unit = a.value("unit", "?");
  std::string out = fmt::format(
      "Allan deviation of {}\n{} samples at {} Hz{}, {}; {} missing in {} gaps\n"
      "Figures in {} (IEEE Std 952-1997 read-offs)\n\n",
      a.value("source", "?"), a.value("samples", 0L), Figure(a["rate_hz"]),
      a.value("rate_estimated", false) ? " (from the time stamps)" : "",
      Duration(a["duration_s"].is_number() ? a["duration_s"].get<double>() : NAN),
      a.value("missing_samples", 0L), a["gaps"].size(), unit);
  out += fmt::format("{:<5}{:>14}  {:>22}  {:>14}  {:>14}\n", "axis", "noise density",
                     "bias instability", "random walk", "max drift");
  out += fmt::format("{:<5}{:>14}  {:>22}  {:>14}  {:>14}\n", "", unit + "/rtHz", unit + " (at tau)",
                     unit + "/rts", unit + " (1 min)");
  for (const char* axis : {"x", "y", "z"}) {
    const json& x = a["axes"][axis];
    const std::string at = x["bias_instability_tau_s"].is_number()
                               ? fmt::format(" ({:.3g} s)", x["bias_instability_tau_s"].get<double>())
                               : "";
    out += fmt::format("{:<5}{:>14}  {:>22}  {:>14}  {:>14}\n", axis, Figure(x["noise_density"]),
                       Figure(x["bias_instability"]) + at,
                       Figure(x["random_walk"]) + (x.value("random_walk_observed", false) ? "" : "*"),
                       Figure(x["max_drift"]));
  }
  out += "  * not observed in this record: an upper bound\n";
  if (a["temperature_c"].is_object()) {
    out += fmt::format("\nTemperature {:.2f} .. {:.2f} degC; correlation of the 1-minute means:",
                       a["temperature_c"]["min"].get<double>(), a["temperature_c"]["max"].get<double>());
    for (const char* axis : {"x", "y", "z"})
      out += fmt::format(" {} {}", axis, Figure(a["axes"][axis]["temperature_correlation"]));
    out += "\n";
  }
  bool header = false;
  for (const char* axis : {"x", "y", "z"})
    for (const json& note : a["axes"][axis]["notes"]) {
      if (!header) out += "\nNotes:\n";
      header = true;
      out += fmt::format("  {}: {}\n", axis, note.get<std::string>());
    }
  return out;
}

}  // namespace accelcal

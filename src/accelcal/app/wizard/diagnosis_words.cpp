#include "accelcal/app/wizard/diagnosis_words.h"

#include <cctype>
#include <cmath>
#include <utility>

#include <fmt/core.h>
#include <fmt/format.h>


namespace accelcal {
namespace {

// The corner pose (1, 1, 1)/sqrt(3) loads u_x u_y u_z = g^3 / (3 sqrt 3): where cross-axis
// coupling shows most.
double CornerProduct(double g) { return g * g / (3.0 * std::sqrt(3.0)); }

// "x +1.2, y -0.3, z +0.0" from three parameters times `factor`.
std::string PerAxis(const std::vector<double>& p, double factor, const char* format) {
  if (p.size() != 3) return "?";
  const char* axes[] = {"x", "y", "z"};
  std::vector<std::string> parts;
  for (int i = 0; i < 3; ++i) parts.push_back(std::string(axes[i]) + " " + fmt::format(fmt::runtime(format), p[static_cast<size_t>(i)] * factor));
  return fmt::format("{}", fmt::join(parts, ", "));
}

double First(const std::vector<double>& v) { return v.empty() ? kNaN : v.front(); }

std::string Generic(const AdoptedEffect& e) {
  std::vector<std::string> parts;
  for (size_t i = 0; i < e.parameters.size(); ++i)
    parts.push_back(fmt::format("{} {:.3g} {}", i < e.parameter_names.size() ? e.parameter_names[i] : "?",
                                e.parameters[i], i < e.parameter_units.size() ? e.parameter_units[i] : ""));
  return fmt::format("an effect the basic model lacks ({}): {}", e.name, fmt::join(parts, ", "));
}

std::string Capitalized(std::string s) {
  if (!s.empty()) s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
  return s;
}

}  // namespace

std::string PlainEffectName(const std::string& name) {
  static const std::pair<const char*, const char*> kNames[] = {
      {"radius_offset", "a wrong turntable radius"}, {"rpm_scale", "a wrong table speed"},
      {"size_effect", "the sensor's size"}, {"turntable_tilt", "a tilted turntable"},
      {"quadratic_nonlinearity", "a bent response"}, {"cubic_nonlinearity", "an S-shaped response"},
      {"cross_axis_coupling", "axes responding to each other"},
      {"temperature_bias", "a zero-g level moving with temperature"},
      {"temperature_scale", "a sensitivity changing with temperature"},
      {"bias_drift", "a drifting zero-g level"},
      // Rivals outside the library (calibration/diagnosis/rival_explanations.h).
      {"turntable_bias_shift", "a zero-g level that shifts while the table turns"},
      {"bias_step", "a zero-g level that jumped once (a knock, the sensor reseated)"},
      {"scale_asymmetry", "a sensitivity that differs for up and down"}};
  for (const auto& [key, words] : kNames)
    if (name == key) return words;
  return name;
}

std::string WithPlainEffectNames(std::string text, const std::vector<std::string>& names) {
  for (const std::string& name : names)
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1))
      text.replace(at, name.size(), PlainEffectName(name));
  return text;
}

bool IsBenchError(const std::string& name) {
  return name == "radius_offset" || name == "rpm_scale" || name == "size_effect" || name == "turntable_tilt";
}

std::string EffectInPlainWords(const AdoptedEffect& e, double g) {
  const std::vector<double>& p = e.parameters;
  const double p0 = First(p), s0 = First(e.uncertainty);
  if (e.name == "radius_offset" && std::isfinite(p0))
    return fmt::format("the turntable radius seems {:.1f} mm {} than entered (+-{:.2g} mm)",
                       std::abs(p0) * 1000.0, p0 >= 0 ? "longer" : "shorter", s0 * 1000.0);
  if (e.name == "rpm_scale" && std::isfinite(p0))
    return fmt::format("the turntable seems to turn {:.2f} % {} than entered (+-{:.2g} %)",
                       std::abs(p0) * 100.0, p0 >= 0 ? "faster" : "slower", s0 * 100.0);
  if (e.name == "size_effect")
    return "each axis senses at a point off the one the radius was measured to: " +
           PerAxis(p, 1000.0, "{:+.1f}") + " mm";
  if (e.name == "turntable_tilt")
    return "the turntable's spin axis is not vertical" +
           (e.interpretation.empty() ? std::string() : ": " + e.interpretation) + "; level the turntable";
  if (e.name == "quadratic_nonlinearity")
    return "the sensor's output is not quite a straight line: at 1 g it bends by " +
           PerAxis(p, g * g, "{:+.1f}") + " counts";
  if (e.name == "cubic_nonlinearity")
    return "the sensor's output is not quite a straight line (an S-bend): at 1 g by " +
           PerAxis(p, g * g * g, "{:+.1f}") + " counts";
  if (e.name == "cross_axis_coupling" && std::isfinite(p0))
    return fmt::format("each axis also responds to the other two together: {:.1f} mm/s^2 on a corner pose",
                       p0 * CornerProduct(g) * 1000.0);
  if (e.name == "temperature_bias")
    return "the zero-g level moves with temperature: " + PerAxis(p, 1.0, "{:+.2f}") + " counts per degC";
  if (e.name == "temperature_scale")
    return "the sensitivity changes with temperature: " + PerAxis(p, 100.0, "{:+.3f}") + " % per degC";
  if (e.name == "bias_drift")
    return "the zero-g level drifts during the session: " + PerAxis(p, 60.0, "{:+.2f}") + " counts per minute";
  return Generic(e);
}

DiagnosisWords DiagnosisInPlainWords(const DiagnosisReport& r, double g) {
  DiagnosisWords w;
  auto say = [&](const std::string& text) { w.lines.push_back(text); };  // the front ends wrap
  if (r.adopted.empty()) {
    if (!r.unexplained) {
      say("The basic model explains every capture within the sensor's noise: nothing to correct.");
    } else {
      say("The captures disagree with the basic model more than the sensor's noise explains, and "
          "no known effect explains it; the calibration keeps the basic model.");
      if (r.ambiguous.size() == 2)
        say(fmt::format("Two explanations fit alike and these captures cannot tell them apart: {} or {}.",
                        PlainEffectName(r.ambiguous[0]), PlainEffectName(r.ambiguous[1])));
      if (!r.next_captures.empty())
        say("To find out, capture " + WithPlainEffectNames(r.next_captures, r.ambiguous));
    }
    w.prompt = "Press Enter to continue (d shows the statistics).";
    return w;
  }
  say(r.adopted.size() == 1 ? "The diagnosis found one thing the basic model lacks:"
                            : fmt::format("The diagnosis found {} things the basic model lacks:", r.adopted.size()));
  bool bench = false, sensor = false;
  for (const AdoptedEffect& e : r.adopted) {
    say("- " + EffectInPlainWords(e, g) + ".");
    (IsBenchError(e.name) ? bench : sensor) = true;
  }
  if (!r.stages.empty())
    say(fmt::format("With {} the fit's error drops from {:.1f} to {:.1f} mm/s^2 (the noise explains {:.1f}).",
                    r.adopted.size() == 1 ? "it" : "them", r.stages.front().residual_rms_mps2 * 1000.0,
                    r.final_fit.residual_rms_mps2 * 1000.0, r.noise_rms_mps2 * 1000.0));
  const std::string action = bench && sensor ? "correct the bench and the sensor's model and refit"
                             : bench        ? (r.adopted.size() == 1 ? "correct it and refit" : "correct them and refit")
                                            : (r.adopted.size() == 1 ? "add it to the calibration"
                                                                     : "add them to the calibration");
  std::vector<std::string> named;
  for (const AdoptedEffect& e : r.adopted) named.push_back(PlainEffectName(e.name));
  const std::string what = r.adopted.size() == 1 ? Capitalized(EffectInPlainWords(r.adopted[0], g))
                                                 : Capitalized(fmt::format("{}", fmt::join(named, " and ")));
  w.prompt = fmt::format("{}: {} (recommended), or keep the basic model?", what, action);
  // The key bar's short form.
  w.recommended_action = bench ? "refit (recommended)" : "add it (recommended)";
  w.asks = true;
  return w;
}

}  // namespace accelcal

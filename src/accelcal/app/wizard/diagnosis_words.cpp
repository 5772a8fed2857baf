#include "accelcal/app/wizard/diagnosis_words.h"

#include <cctype>
#include <cmath>
#include <optional>

#include <fmt/core.h>
#include <fmt/format.h>

#include "accelcal/calibration/diagnosis/bench_statement.h"
#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/calibration/diagnosis/rival_explanations.h"

namespace accelcal {
namespace {

// "x +1.2, y -0.3, z +0.0" with `decimals` digits after the point; "?" unless three values.
std::string ValuesPerAxis(const std::vector<double>& values, int decimals) {
  if (values.size() != 3) return "?";
  const char* axes[] = {"x", "y", "z"};
  std::vector<std::string> parts;
  for (size_t i = 0; i < 3; ++i) parts.push_back(fmt::format("{} {:+.{}f}", axes[i], values[i], decimals));
  return fmt::format("{}", fmt::join(parts, ", "));
}

// An effect's statement (bench_statement.h) as the sentence the technician reads.
std::string SaidOf(const BenchStatement& s) {
  const BenchQuantity& q = s.size;
  const double value = q.values.empty() ? kNaN : q.values.front();
  switch (q.shape) {
    case BenchQuantity::Shape::kNone:
      return s.lead + s.tail;
    case BenchQuantity::Shape::kValue:
      return fmt::format("{}{:.{}f} {}{}", s.lead, value, q.decimals, q.unit, s.tail);
    case BenchQuantity::Shape::kDirection:
      return fmt::format("{}{:.{}f} {} {}{} (+-{:.2g} {})", s.lead, std::abs(value), q.decimals, q.unit,
                         value >= 0 ? q.positive : q.negative, s.tail, q.sigma, q.unit);
    case BenchQuantity::Shape::kPerAxis:
      return s.lead + ValuesPerAxis(q.values, q.decimals) + " " + q.unit + s.tail;
  }
  return s.lead + s.tail;
}

// An effect that says nothing in bench terms (or that this version does not know): its name and
// parameters.
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
  const Effect* effect = FindEffect(name);
  if (effect == nullptr) effect = FindRival(name);  // a rival outside the library is said too
  if (effect == nullptr || effect->PlainName().empty()) return name;
  return std::string(effect->PlainName());
}

std::string WithPlainEffectNames(std::string text, const std::vector<std::string>& names) {
  for (const std::string& name : names)
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1))
      text.replace(at, name.size(), PlainEffectName(name));
  return text;
}

bool IsBenchError(const std::string& name) {
  const Effect* effect = FindEffect(name);
  return effect != nullptr && effect->IsBenchError();
}

std::string EffectInPlainWords(const AdoptedEffect& e, double g) {
  const Effect* effect = FindEffect(e.name);
  const std::optional<BenchStatement> said =
      effect == nullptr ? std::nullopt : effect->InBenchTerms(e.parameters, e.uncertainty, e.interpretation, g);
  return said ? SaidOf(*said) : Generic(e);
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

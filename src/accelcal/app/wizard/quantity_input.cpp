#include "accelcal/app/wizard/quantity_input.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

struct NumberAndUnit {
  bool ok = false;
  double number = kNaN;
  std::string unit;  // lower case, no blanks
  bool ambiguous = false;  // "1,200": 1.2 or 1200
};

std::string_view Trim(std::string_view s);

// Why an ambiguous number is refused, for either field.
std::string AmbiguousMessage(std::string_view text) {
  const std::string_view t = Trim(text);
  const size_t comma = t.find(',');
  return fmt::format("'{}' could be {}.{} or {}{}: type it without the comma, or with a point",
                     t, t.substr(0, comma), t.substr(comma + 1), t.substr(0, comma),
                     t.substr(comma + 1));
}

std::string_view Trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// A decimal comma ("0,12", as typed on a Spanish keyboard) read as a point: only a single comma
// in a number without a point.
std::string WithDecimalPoint(std::string_view t) {
  std::string s(t);
  const size_t comma = s.find(',');
  if (comma != std::string::npos && s.find(',', comma + 1) == std::string::npos &&
      s.find('.') == std::string::npos)
    s[comma] = '.';
  return s;
}

// "1,200" may be 1.2 or 1200 (a thousands separator): a nonzero whole number, a comma and
// exactly three digits. Refused rather than guessed ("0,125" is not ambiguous).
bool AmbiguousComma(std::string_view t) {
  const size_t comma = t.find(',');
  if (comma == std::string_view::npos || comma == 0) return false;
  for (size_t i = 0; i < comma; ++i)
    if (!std::isdigit(static_cast<unsigned char>(t[i]))) return false;
  if (t.substr(0, comma).find_first_not_of('0') == std::string_view::npos) return false;
  size_t digits = 0;
  while (comma + 1 + digits < t.size() && std::isdigit(static_cast<unsigned char>(t[comma + 1 + digits])))
    ++digits;
  return digits == 3;
}

NumberAndUnit Split(std::string_view text) {
  NumberAndUnit out;
  if (AmbiguousComma(Trim(text))) {
    out.ambiguous = true;
    return out;
  }
  const std::string t = WithDecimalPoint(Trim(text));
  const char* end = t.data() + t.size();
  const auto [ptr, ec] = std::from_chars(t.data(), end, out.number);
  if (ec != std::errc() || !std::isfinite(out.number)) return out;
  for (const char* p = ptr; p != end; ++p)
    if (!std::isspace(static_cast<unsigned char>(*p)))
      out.unit += static_cast<char>(std::tolower(static_cast<unsigned char>(*p)));
  out.ok = true;
  return out;
}

// The number with its unit as typed, for messages ("12 m").
std::string AsTyped(const NumberAndUnit& q, std::string_view default_unit) {
  return fmt::format("{:g} {}", q.number, q.unit.empty() ? default_unit : q.unit);
}

// A radius out of range: suggest the unit that makes the same number plausible and nearest a
// typical bench radius (10 cm), so "12 m" suggests 12 cm and "120" suggests 120 mm.
std::string RadiusSuggestion(double number) {
  std::string best;
  double best_distance = 1e300;
  for (const auto& [unit, factor] : {std::pair{"mm", 0.001}, std::pair{"cm", 0.01},
                                     std::pair{"m", 1.0}}) {
    const double m = number * factor;
    if (!IsPlausibleTurntableRadius(m)) continue;
    const double distance = std::abs(std::log10(m / 0.1));
    if (distance < best_distance) {
      best_distance = distance;
      best = fmt::format(": did you mean {:g} {}?", number, unit);
    }
  }
  if (!best.empty()) return best;
  return fmt::format(" (expected {:g} mm to {:g} m)", kMinRadiusM * 1000, kMaxRadiusM);
}

bool IsRadiusUnit(const std::string& unit) { return unit == "mm" || unit == "cm" || unit == "m"; }
bool IsSpeedUnit(const std::string& unit) {
  return unit == "rpm" || unit == "rps" || unit == "hz" || unit == "rad/s";
}

}  // namespace

bool IsBlank(std::string_view text) { return Trim(text).empty(); }

TurntableField FieldOfUnit(std::string_view text) {
  const NumberAndUnit q = Split(text);
  if (!q.ok) return TurntableField::kNone;
  if (IsRadiusUnit(q.unit)) return TurntableField::kRadius;
  if (IsSpeedUnit(q.unit)) return TurntableField::kSpeed;
  return TurntableField::kNone;
}

QuantityResult ParseRadius(std::string_view text) {
  const NumberAndUnit q = Split(text);
  if (q.ambiguous) return {kNaN, AmbiguousMessage(text)};
  if (!q.ok)
    return {kNaN, fmt::format("'{}' is not a radius: give a number with mm, cm or m (e.g. 120 mm)",
                              Trim(text))};
  double factor = 1.0;
  if (q.unit == "mm") factor = 0.001;
  else if (q.unit == "cm") factor = 0.01;
  else if (IsSpeedUnit(q.unit))
    return {kNaN, fmt::format("{} is a speed, not a radius: it goes in the speed field",
                              AsTyped(q, ""))};
  else if (q.unit != "m" && !q.unit.empty())
    return {kNaN, fmt::format("unknown unit '{}' for a radius: use mm, cm or m", q.unit)};
  const double radius_m = q.number * factor;
  if (!IsPlausibleTurntableRadius(radius_m))
    return {kNaN, fmt::format("{} is not a plausible turntable radius{}", AsTyped(q, "m"),
                              RadiusSuggestion(q.number))};
  return {radius_m, ""};
}

QuantityResult ParseRpm(std::string_view text) {
  const NumberAndUnit q = Split(text);
  if (q.ambiguous) return {kNaN, AmbiguousMessage(text)};
  if (!q.ok)
    return {kNaN, fmt::format("'{}' is not a speed: give rpm (e.g. 120), rps, Hz or rad/s", Trim(text))};
  double factor = 1.0;
  if (q.unit == "rps" || q.unit == "hz") factor = 60.0;
  else if (q.unit == "rad/s") factor = 60.0 / (2.0 * M_PI);
  else if (IsRadiusUnit(q.unit))
    return {kNaN, fmt::format("{} is a radius, not a speed: it goes in the radius field",
                              AsTyped(q, ""))};
  else if (q.unit != "rpm" && !q.unit.empty())
    return {kNaN, fmt::format("unknown unit '{}' for a speed: use rpm, rps, Hz or rad/s", q.unit)};
  const double rpm = q.number * factor;
  if (!IsPlausibleTurntableRpm(rpm))
    return {kNaN, fmt::format("{} ({:g} rpm) is not a plausible turntable speed (expected {:g} to "
                              "{:g} rpm)", AsTyped(q, "rpm"), rpm, kMinRpm, kMaxRpm)};
  return {rpm, ""};
}

std::string CheckTurntableAgainstRange(const TurntableSetup& setup, double range_g,
                                       const SensorModel& rough_model, const AdcRange& adc_range,
                                       const TurntableStabilityOptions& options) {
  const double g = options.gravity_mps2;
  const double centripetal_mps2 = setup.ExpectedCentripetalMps2();
  const double limit_mps2 = range_g * g * (1.0 - options.range_margin);
  if (centripetal_mps2 > limit_mps2)
    return fmt::format("{:g} rpm at {:g} m gives {:.1f} g on the radial axis, beyond the "
                       "accelerometer's +-{:g} g range: lower the speed or the radius",
                       setup.rpm, setup.radius_m, centripetal_mps2 / g, range_g);
  return CheckTurntablePlan(setup, rough_model, adc_range, options);
}

}  // namespace accelcal

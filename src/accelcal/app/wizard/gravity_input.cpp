#include "accelcal/app/wizard/gravity_input.h"

#include <cctype>
#include <cmath>
#include <vector>

#include <fmt/core.h>

#include "accelcal/base/capture.h"
#include "accelcal/base/text_scan.h"

namespace accelcal {
namespace {

constexpr const char* kExpected =
    "give the measured value (9.7803, or 9.78030 +- 0.00002 m/s^2), the place (lat -34.9 alt 43), "
    "or say 'standard'";

std::string Lower(std::string_view text) {
  std::string out;
  for (char c : text) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Words separated by blanks and commas; "+-" and "±" become words of their own.
std::vector<std::string> Words(std::string text) {
  for (const std::string_view pm : {"\u00b1", "+/-"}) {
    for (size_t at; (at = text.find(pm)) != std::string::npos;) text.replace(at, pm.size(), " +- ");
  }
  for (size_t at = 0; (at = text.find("+-", at)) != std::string::npos; at += 4) text.replace(at, 2, " +- ");
  std::vector<std::string> words;
  std::string word;
  for (char c : text) {
    if (c == ' ' || c == '\t' || c == ',') {
      if (!word.empty()) words.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(word);
  return words;
}

// Half a unit of the last digit typed, as a rectangular distribution's standard uncertainty
// (GUM 4.3.7): "9.7803" -> 0.00005 / sqrt(3).
double ResolutionSigma(const std::string& number) {
  const size_t dot = number.find('.');
  const size_t e = number.find_first_of("eE");
  if (e != std::string::npos) return kNaN;  // "9.78e0": no resolution to read
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(number.size() - dot - 1);
  return 0.5 * std::pow(10.0, -decimals) / std::sqrt(3.0);
}

bool Number(const std::string& word, double* value) {
  return detail::ParseDouble(word, value) && std::isfinite(*value);
}

bool IsUnit(const std::string& word, std::initializer_list<const char*> units) {
  for (const char* u : units)
    if (word == u) return true;
  return false;
}

GravityAnswer Refuse(std::string why) { return {GravitySpec::Standard(), std::move(why)}; }

GravityAnswer Checked(GravitySpec spec) {
  if (std::string why = spec.Validate(); !why.empty()) return Refuse(why);
  return {spec, ""};
}

// "9.7803", "9.7803 m/s^2", "9.78030 +- 0.00002", "9.78030 m/s^2 +- 0.00002 m/s^2".
GravityAnswer ParseMeasured(const std::vector<std::string>& w) {
  size_t i = 0;
  double g = kNaN;
  if (!Number(w[i], &g)) return Refuse(fmt::format("'{}' is not a number: {}", w[i], kExpected));
  const double resolution = ResolutionSigma(w[i++]);
  const auto skip_unit = [&] {
    if (i < w.size() && IsUnit(w[i], {"m/s^2", "m/s2", "m/s²"})) ++i;
  };
  skip_unit();
  double sigma = resolution;
  if (i < w.size() && w[i] == "+-") {
    ++i;
    if (i >= w.size() || !Number(w[i], &sigma))
      return Refuse("after '+-' give the standard uncertainty in m/s^2 (e.g. +- 0.00002)");
    ++i;
    skip_unit();
  }
  if (i < w.size()) return Refuse(fmt::format("unexpected '{}': {}", w[i], kExpected));
  if (g > 900.0 && g < 1000.0)
    return Refuse(fmt::format("{:g} looks like Gal (cm/s^2): in m/s^2 that is {:g}", g, g / 100.0));
  return Checked(GravitySpec::Given(g, sigma));
}

// "lat -34.9 alt 43", "latitude -34.9 deg altitude 43 m", "lat -34.9".
GravityAnswer ParseLocation(const std::vector<std::string>& w) {
  double lat = kNaN;
  double alt = 0.0;
  for (size_t i = 0; i < w.size(); ++i) {
    const bool is_lat = IsUnit(w[i], {"lat", "latitude"});
    const bool is_alt = IsUnit(w[i], {"alt", "altitude", "height"});
    if (!is_lat && !is_alt) return Refuse(fmt::format("unexpected '{}': {}", w[i], kExpected));
    double value = kNaN;
    if (i + 1 >= w.size() || !Number(w[i + 1], &value))
      return Refuse(fmt::format("'{}' needs a number after it ({})", w[i],
                                is_lat ? "degrees, south negative" : "metres above the ellipsoid"));
    (is_lat ? lat : alt) = value;
    ++i;
    if (i + 1 < w.size() && IsUnit(w[i + 1], is_lat ? std::initializer_list<const char*>{"deg", "°"}
                                                    : std::initializer_list<const char*>{"m"}))
      ++i;
  }
  if (std::isnan(lat)) return Refuse("a location needs its latitude: lat DEG [alt M]");
  return Checked(GravitySpec::FromLocation(lat, alt));
}

}  // namespace

GravityAnswer ParseGravityAnswer(std::string_view text) {
  const std::vector<std::string> w = Words(Lower(detail::TrimBlanks(text)));
  if (w.empty()) return Refuse(std::string("no gravity given: ") + kExpected);
  if (w.size() == 1 && (w[0] == "standard" || w[0] == "std"))
    return {GravitySpec::Standard(), ""};
  if (w[0] == "standard" || w[0] == "std")
    return Refuse(std::string("'standard' stands alone: ") + kExpected);
  if (IsUnit(w[0], {"lat", "latitude", "alt", "altitude", "height"})) return ParseLocation(w);
  return ParseMeasured(w);
}

std::string GravityAnswerText(const GravitySpec& gravity) {
  switch (gravity.source) {
    case GravitySpec::Source::kStandard: return "standard";
    case GravitySpec::Source::kWgs84:
      return fmt::format("lat {} alt {}", detail::FormatNumber(gravity.latitude_deg),
                         detail::FormatNumber(gravity.altitude_m));
    case GravitySpec::Source::kGiven:
      if (std::isnan(gravity.sigma_mps2)) return detail::FormatNumber(gravity.gravity_mps2);
      return fmt::format("{} +- {}", detail::FormatNumber(gravity.gravity_mps2),
                         detail::FormatNumber(gravity.sigma_mps2));
  }
  return "standard";
}

}  // namespace accelcal

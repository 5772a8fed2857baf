#include "accelcal/base/gravity.h"

#include <cmath>

#include <fmt/core.h>

namespace accelcal {
namespace {

// WGS84 (NIMA TR8350.2, tables 3.1-3.3).
constexpr double kSemiMajorAxisM = 6378137.0;
constexpr double kFlattening = 1.0 / 298.257223563;
constexpr double kGammaEquatorMps2 = 9.7803253359;
constexpr double kSomiglianaK = 0.00193185265241;     // (b gamma_p) / (a gamma_e) - 1
constexpr double kFirstEccentricitySq = 0.00669437999013;
constexpr double kGeodeticM = 0.00344978650684;       // omega^2 a^2 b / GM

// Plausible range for gravity anywhere a bench can stand (the Earth's surface spans about
// 9.76..9.84 m/s^2); outside it the value is almost surely a unit mistake.
constexpr double kMinPlausibleMps2 = 9.7;
constexpr double kMaxPlausibleMps2 = 9.9;
constexpr double kMaxPlausibleSigmaMps2 = 0.1;

// " +- 0.00050" (5 decimals, as the value), or nothing when the uncertainty is not stated.
std::string PlusMinus(double sigma_mps2) {
  if (std::isnan(sigma_mps2)) return "";
  return fmt::format(" +- {:.5f}", sigma_mps2);
}

}  // namespace

double NormalGravityWgs84Mps2(double latitude_deg, double height_m) {
  const double s = std::sin(latitude_deg * M_PI / 180.0);
  const double s2 = s * s;
  const double on_ellipsoid =
      kGammaEquatorMps2 * (1.0 + kSomiglianaK * s2) / std::sqrt(1.0 - kFirstEccentricitySq * s2);
  const double a = kSemiMajorAxisM;
  const double h = height_m;
  const double free_air =
      1.0 - 2.0 / a * (1.0 + kFlattening + kGeodeticM - 2.0 * kFlattening * s2) * h +
      3.0 * h * h / (a * a);
  return on_ellipsoid * free_air;
}

GravitySpec GravitySpec::Standard() { return GravitySpec{}; }

GravitySpec GravitySpec::Given(double gravity_mps2, double sigma_mps2) {
  GravitySpec g;
  g.source = Source::kGiven;
  g.gravity_mps2 = gravity_mps2;
  g.sigma_mps2 = sigma_mps2;
  return g;
}

GravitySpec GravitySpec::FromLocation(double latitude_deg, double altitude_m) {
  GravitySpec g;
  g.source = Source::kWgs84;
  g.latitude_deg = latitude_deg;
  g.altitude_m = altitude_m;
  g.gravity_mps2 = NormalGravityWgs84Mps2(latitude_deg, altitude_m);
  g.sigma_mps2 = std::hypot(kWgs84AnomalySigmaMps2, kWgs84ModelSigmaMps2);
  return g;
}

std::string GravitySpec::Validate() const {
  if (source == Source::kWgs84) {
    if (!std::isfinite(latitude_deg) || std::fabs(latitude_deg) > 90.0)
      return fmt::format("latitude {} deg is outside -90..90", latitude_deg);
    if (!std::isfinite(altitude_m) || altitude_m < -500.0 || altitude_m > 9000.0)
      return fmt::format("altitude {} m is outside -500..9000 m (is it in metres?)", altitude_m);
  }
  if (!std::isfinite(gravity_mps2) || gravity_mps2 < kMinPlausibleMps2 ||
      gravity_mps2 > kMaxPlausibleMps2)
    return fmt::format("gravity {} m/s^2 is outside the plausible {}..{} m/s^2 (is it in m/s^2?)",
                       gravity_mps2, kMinPlausibleMps2, kMaxPlausibleMps2);
  // NaN: not stated. Above 0.1 m/s^2 the value says nothing (the whole Earth spans 0.08).
  if (!std::isnan(sigma_mps2) && !(sigma_mps2 >= 0.0 && sigma_mps2 <= kMaxPlausibleSigmaMps2))
    return fmt::format("gravity uncertainty {} m/s^2 is outside 0..{} m/s^2", sigma_mps2,
                       kMaxPlausibleSigmaMps2);
  return {};
}

std::string GravitySpec::SourceName() const {
  switch (source) {
    case Source::kStandard: return "standard";
    case Source::kGiven: return "given";
    case Source::kWgs84: return "wgs84";
  }
  return "?";
}

std::string GravitySpec::Describe() const {
  switch (source) {
    case Source::kStandard:
      return fmt::format("{:.5f}{} m/s^2 (standard gravity, not the local value)", gravity_mps2,
                         PlusMinus(sigma_mps2));
    case Source::kGiven:
      return fmt::format("{:.5f}{} m/s^2 (measured)", gravity_mps2, PlusMinus(sigma_mps2));
    case Source::kWgs84:
      return fmt::format("{:.5f}{} m/s^2 (WGS84 normal gravity at latitude {:.4f} deg, altitude "
                         "{:.1f} m)", gravity_mps2, PlusMinus(sigma_mps2), latitude_deg, altitude_m);
  }
  return "?";
}

}  // namespace accelcal

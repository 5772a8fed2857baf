// Local gravity: the magnitude of the specific force a sensor at rest feels, m/s^2.
//
// Three ways to choose it, and every output states which one was used (GravitySpec::Describe):
//  - the standard value 9.80665 m/s^2 (CGPM 1901, ISO 80000-3): a convention, not the local
//    value; chosen explicitly (the wizard asks),
//  - a measured value given by the user, with its standard uncertainty,
//  - WGS84 normal gravity at a latitude and ellipsoidal height: Somigliana's closed formula on
//    the ellipsoid with the second-order free-air correction for height, both as given in
//    NIMA TR8350.2, "Department of Defense World Geodetic System 1984", 3rd ed. (2000),
//    eqs. 4-1 and 4-3, with the WGS84 defining and derived constants of its tables 3.1-3.3.
//    Normal gravity ignores local anomalies (up to a few 1e-4 relative); a measured value is
//    better when the lab has one.
//
// Each carries its standard uncertainty u (1-sigma, m/s^2), for the uncertainty budget:
//  - measured: the u the user states; when none is stated, the resolution of the value as
//    typed, half a unit of its last digit taken as a rectangular distribution (/sqrt(3), GUM
//    4.3.7), so that "9.7803" means 9.7803 +- 0.000029;
//  - WGS84: the model error of the second-order free-air series (below 1e-6 m/s^2 up to 9 km)
//    plus the local anomaly the normal field ignores, taken as kWgs84AnomalySigmaMps2 (50 mGal:
//    the order of free-air anomalies away from mountains; in mountains they reach a few hundred
//    mGal and a measured value is needed);
//  - standard: the spread of gravity over the Earth's surface, about 9.76..9.84 m/s^2, taken as
//    a rectangular distribution of half-width 0.04 m/s^2 around 9.80665 (0.04 / sqrt(3)).
#pragma once

#include <limits>
#include <string>

namespace accelcal {

inline constexpr double kStandardGravityMps2 = 9.80665;
// Standard uncertainty of the standard value as the local gravity of an unknown place, m/s^2.
inline constexpr double kStandardGravitySigmaMps2 = 0.04 / 1.7320508075688772;
// Standard uncertainty of WGS84 normal gravity as the local value: the anomaly, m/s^2.
inline constexpr double kWgs84AnomalySigmaMps2 = 0.0005;
// Standard uncertainty of the second-order free-air series below 9 km, m/s^2.
inline constexpr double kWgs84ModelSigmaMps2 = 1e-6;

// WGS84 normal gravity, m/s^2, at geodetic latitude `latitude_deg` (-90..90) and height
// `height_m` above the ellipsoid (valid for heights of a few km, the free-air series' range).
double NormalGravityWgs84Mps2(double latitude_deg, double height_m);

struct GravitySpec {
  enum class Source { kStandard, kGiven, kWgs84 };
  Source source = Source::kStandard;
  double gravity_mps2 = kStandardGravityMps2;
  // Standard uncertainty (1-sigma) of gravity_mps2 as the local value, m/s^2; NaN: not stated
  // (a calibration file written before it was recorded).
  double sigma_mps2 = kStandardGravitySigmaMps2;
  double latitude_deg = 0.0;  // kWgs84 only
  double altitude_m = 0.0;    // kWgs84 only

  static GravitySpec Standard();
  // A measured value; `sigma_mps2` its standard uncertainty (NaN: not stated).
  static GravitySpec Given(double gravity_mps2, double sigma_mps2 = std::numeric_limits<double>::quiet_NaN());
  static GravitySpec FromLocation(double latitude_deg, double altitude_m);

  // Empty when usable, else why not (e.g. 0.98 m/s^2 is rejected as a probable unit mistake,
  // a negative or implausibly large uncertainty too).
  std::string Validate() const;
  // One line: "9.80665 +- 0.02309 m/s^2 (standard gravity, not the local value)",
  // "9.81744 +- 0.00002 m/s^2 (measured)", "9.80373 +- 0.00050 m/s^2 (WGS84 normal gravity at
  // latitude -34.9000 deg, altitude 43.0 m)"; without "+- u" when it is not stated.
  std::string Describe() const;
  bool is_standard() const { return source == Source::kStandard; }
  // "standard", "given" or "wgs84" (as stored in the calibration file).
  std::string SourceName() const;
};

}  // namespace accelcal

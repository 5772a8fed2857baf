// Local gravity: the magnitude of the specific force a sensor at rest feels, m/s^2.
//
// Three ways to choose it, and every output states which one was used (GravitySpec::Describe):
//  - the standard value 9.80665 m/s^2 (the default; CGPM 1901, ISO 80000-3),
//  - a measured value given by the user,
//  - WGS84 normal gravity at a latitude and ellipsoidal height: Somigliana's closed formula on
//    the ellipsoid with the second-order free-air correction for height, both as given in
//    NIMA TR8350.2, "Department of Defense World Geodetic System 1984", 3rd ed. (2000),
//    eqs. 4-1 and 4-3, with the WGS84 defining and derived constants of its tables 3.1-3.3.
//    Normal gravity ignores local anomalies (up to a few 1e-4 relative); a measured value is
//    better when the lab has one.
#pragma once

#include <string>

namespace accelcal {

inline constexpr double kStandardGravityMps2 = 9.80665;

// WGS84 normal gravity, m/s^2, at geodetic latitude `latitude_deg` (-90..90) and height
// `height_m` above the ellipsoid (valid for heights of a few km, the free-air series' range).
double NormalGravityWgs84Mps2(double latitude_deg, double height_m);

struct GravitySpec {
  enum class Source { kStandard, kGiven, kWgs84 };
  Source source = Source::kStandard;
  double gravity_mps2 = kStandardGravityMps2;
  double latitude_deg = 0.0;  // kWgs84 only
  double altitude_m = 0.0;    // kWgs84 only

  static GravitySpec Standard();
  static GravitySpec Given(double gravity_mps2);
  static GravitySpec FromLocation(double latitude_deg, double altitude_m);

  // Empty when usable, else why not (e.g. 0.98 m/s^2 is rejected as a probable unit mistake).
  std::string Validate() const;
  // One line: "9.80665 m/s^2 (standard gravity)", "9.81744 m/s^2 (given)",
  // "9.80373 m/s^2 (WGS84 normal gravity at latitude -34.9000 deg, altitude 43.0 m)".
  std::string Describe() const;
  // "standard", "given" or "wgs84" (as stored in the calibration file).
  std::string SourceName() const;
};

}  // namespace accelcal

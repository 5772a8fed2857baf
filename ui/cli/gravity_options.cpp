#include "cli/gravity_options.h"

#include "accelcal/base/error.h"

namespace accelcal::cli {

void GravityFlags::Bind(CLI::App& app) {
  gravity = app.add_option("--gravity", gravity_mps2,
                           "Local gravity in m/s^2 (measured). Default: standard gravity 9.80665");
  latitude = app.add_option("--latitude", latitude_deg,
                            "Geodetic latitude in degrees (-90..90): use WGS84 normal gravity");
  altitude = app.add_option("--altitude", altitude_m,
                            "Height above the WGS84 ellipsoid in m (with --latitude; default 0)");
  gravity->excludes(latitude);
  gravity->excludes(altitude);
  altitude->needs(latitude);
}

GravitySpec GravityFlags::Resolve() const {
  GravitySpec spec = GravitySpec::Standard();
  if (gravity != nullptr && gravity->count() > 0) spec = GravitySpec::Given(gravity_mps2);
  if (latitude != nullptr && latitude->count() > 0)
    spec = GravitySpec::FromLocation(latitude_deg, altitude_m);
  if (std::string e = spec.Validate(); !e.empty()) throw Error("gravity: " + e);
  return spec;
}

}  // namespace accelcal::cli

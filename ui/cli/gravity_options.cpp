#include "cli/gravity_options.h"

#include "accelcal/app/wizard/gravity_input.h"
#include "accelcal/base/error.h"

namespace accelcal::cli {

void GravityFlags::Bind(CLI::App& app) {
  gravity = app.add_option("--gravity", gravity_text,
                           "Local gravity in m/s^2, measured: G or G+-U (U its standard "
                           "uncertainty; without it, the resolution typed), or 'standard' for "
                           "9.80665. Default: standard gravity");
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
  if (gravity != nullptr && gravity->count() > 0) {
    const GravityAnswer answer = ParseGravityAnswer(gravity_text);
    if (!answer.ok()) throw Error("--gravity: " + answer.error);
    spec = answer.gravity;
  }
  if (latitude != nullptr && latitude->count() > 0)
    spec = GravitySpec::FromLocation(latitude_deg, altitude_m);
  if (std::string e = spec.Validate(); !e.empty()) throw Error("gravity: " + e);
  return spec;
}

std::string GravityFlags::Given() const {
  if (gravity != nullptr && gravity->count() > 0) return "--gravity " + gravity_text;
  if (latitude == nullptr || latitude->count() == 0) return "";
  std::string given = "--latitude " + latitude->as<std::string>();
  if (altitude != nullptr && altitude->count() > 0) given += " --altitude " + altitude->as<std::string>();
  return given;
}

}  // namespace accelcal::cli

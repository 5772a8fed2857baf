// Kalibr's IMU noise file (imu.yaml), as its camera-IMU calibration reads it (Kalibr wiki,
// "IMU Noise Model"; keys as in the sample imu.yaml):
//
//   accelerometer_noise_density  m/s^2/sqrt(Hz)   white noise, continuous time (Allan: N)
//   accelerometer_random_walk    m/s^3/sqrt(Hz)   bias random walk (Allan: rate random walk K)
//   gyroscope_noise_density      rad/s/sqrt(Hz)
//   gyroscope_random_walk        rad/s^2/sqrt(Hz)
//   rostopic                     the IMU's ROS topic
//   update_rate                  Hz, the IMU's sample rate (Kalibr discretizes the densities
//                                with it)
//
// Kalibr takes one figure per sensor, not per axis. An accelerometer bench knows nothing of the
// gyroscope: when its figures are not given, the gyroscope lines are written as comments that
// say what to fill in, and `cannot_hold` says Kalibr will refuse the file until they are.
//
// Also the entry point for the Allan analysis (`accelcal allan`): WriteKalibrImuYaml takes the
// figures directly.
#pragma once

#include <string>

#include "accelcal/io/export/export_result.h"

namespace accelcal {

struct KalibrImuYamlOptions {
  double accelerometer_noise_density = kNaN;  // m/s^2/sqrt(Hz), required, > 0
  double accelerometer_random_walk = kNaN;    // m/s^3/sqrt(Hz), required, > 0
  double gyroscope_noise_density = kNaN;      // rad/s/sqrt(Hz); NaN: unknown (commented out)
  double gyroscope_random_walk = kNaN;        // rad/s^2/sqrt(Hz); NaN: unknown
  double update_rate_hz = kNaN;               // required, > 0
  std::string rostopic = "/imu0";             // letters, digits, '_', '/', '~'
  std::string comment;  // written as '#' lines at the top (e.g. the origin); may hold newlines

  // Empty when valid, else the problem.
  std::string Validate() const;
};

// Throws accelcal::Error when `options` is invalid.
ExportResult WriteKalibrImuYaml(const KalibrImuYamlOptions& options);

// The accelerometer figures Kalibr wants, from an Allan analysis file (`accelcal allan -o`):
// {"unit": "counts" | "m/s^2", "rate_hz": .., "axes": {"x": {"noise_density": N,
// "random_walk": K, ...}, "y": .., "z": ..}}, N in unit/sqrt(Hz), K in unit/s/sqrt(Hz) (the
// rate random walk, IEEE Std 952 Annex C). Counts are turned into m/s^2 with each axis's scale
// of `cal`. Kalibr takes one figure: the worst (largest) axis of each.
struct AllanNoiseFigures {
  double noise_density_mps2_per_sqrt_hz = kNaN;
  double random_walk_mps3_per_sqrt_hz = kNaN;  // NaN when the file has none on any axis
  double rate_hz = kNaN;                        // NaN when the file has none
  char noise_density_axis = '?';                // which axis gave each figure
  char random_walk_axis = '?';
};
// `allan_text` is the file's text. Throws InputError (naming `source_name` and the field) for a
// malformed file.
AllanNoiseFigures AllanNoiseForKalibrText(const std::string& allan_text, const Calibration& cal,
                                          const std::string& source_name);

}  // namespace accelcal

#include "accelcal/io/export/kalibr_imu_yaml.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "accelcal/base/error.h"
#include "accelcal/base/safe_text.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/detail/json_values.h"

namespace accelcal {
namespace {

bool PositiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

// A YAML float that reads back as a float (never as an integer): "100" -> "100.0".
std::string YamlFloat(double v) {
  std::string s = ExportNumber(v);
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

// The value of `axes.<axis>.<key>` as a positive number, NaN when null or absent.
double AxisFigure(const nlohmann::json& axes, const char* axis, const char* key, const std::string& source) {
  if (!axes.contains(axis) || !axes[axis].is_object())
    throw InputError(source, 0, 0, fmt::format("axes.{} is missing", axis));
  const nlohmann::json& a = axes[axis];
  if (!a.contains(key) || a[key].is_null()) return kNaN;
  if (!a[key].is_number() || !PositiveFinite(a[key].get<double>()))
    throw InputError(source, 0, 0, fmt::format("axes.{}.{} is not a positive number", axis, key));
  return a[key].get<double>();
}

}  // namespace

std::string KalibrImuYamlOptions::Validate() const {
  if (!PositiveFinite(accelerometer_noise_density))
    return "the accelerometer noise density (m/s^2/sqrt(Hz)) must be a positive number";
  if (!PositiveFinite(accelerometer_random_walk))
    return "the accelerometer random walk (m/s^3/sqrt(Hz)) must be a positive number";
  if (!std::isnan(gyroscope_noise_density) && !PositiveFinite(gyroscope_noise_density))
    return "the gyroscope noise density must be a positive number";
  if (!std::isnan(gyroscope_random_walk) && !PositiveFinite(gyroscope_random_walk))
    return "the gyroscope random walk must be a positive number";
  if (!PositiveFinite(update_rate_hz)) return "the IMU's update rate (Hz) must be a positive number";
  if (rostopic.empty()) return "the ROS topic is empty";
  for (char ch : rostopic)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '/' && ch != '~')
      return fmt::format("the ROS topic '{}' has a character ROS names do not allow", rostopic);
  return {};
}

ExportResult WriteKalibrImuYaml(const KalibrImuYamlOptions& o) {
  if (const std::string why = o.Validate(); !why.empty()) throw Error(why);
  ExportResult result;
  std::string& t = result.text;
  std::istringstream comment(o.comment);
  // Each line through DisplayText: a CR, NEL or U+2028 in it would end a YAML comment too.
  for (std::string line; std::getline(comment, line);) t += line.empty() ? "#\n" : "# " + DisplayText(line) + "\n";
  t += "#Accelerometers\n";
  t += fmt::format("accelerometer_noise_density: {}  # m/s^2/sqrt(Hz), white noise (continuous time)\n",
                   YamlFloat(o.accelerometer_noise_density));
  t += fmt::format("accelerometer_random_walk: {}  # m/s^3/sqrt(Hz), bias random walk\n",
                   YamlFloat(o.accelerometer_random_walk));
  t += "#Gyroscopes\n";
  const bool gyro_known = !std::isnan(o.gyroscope_noise_density) && !std::isnan(o.gyroscope_random_walk);
  if (!std::isnan(o.gyroscope_noise_density))
    t += fmt::format("gyroscope_noise_density: {}  # rad/s/sqrt(Hz)\n", YamlFloat(o.gyroscope_noise_density));
  else
    t += "# gyroscope_noise_density: UNKNOWN  # rad/s/sqrt(Hz): fill in from the gyroscope's Allan analysis\n";
  if (!std::isnan(o.gyroscope_random_walk))
    t += fmt::format("gyroscope_random_walk: {}  # rad/s^2/sqrt(Hz)\n", YamlFloat(o.gyroscope_random_walk));
  else
    t += "# gyroscope_random_walk: UNKNOWN  # rad/s^2/sqrt(Hz): fill in from the gyroscope's Allan analysis\n";
  t += fmt::format("rostopic: {}  # the IMU's ROS topic\n", o.rostopic);
  t += fmt::format("update_rate: {}  # Hz\n", YamlFloat(o.update_rate_hz));
  if (!gyro_known)
    result.cannot_hold.push_back(
        "the gyroscope's noise (gyroscope_noise_density in rad/s/sqrt(Hz), gyroscope_random_walk "
        "in rad/s^2/sqrt(Hz)): an accelerometer calibration knows nothing of the gyroscope; "
        "Kalibr needs both, so fill in the commented lines (from the gyroscope's Allan analysis) "
        "before using the file");
  result.cannot_hold.push_back(
      "the calibration's bias, scale and misalignment: imu.yaml holds only the noise model "
      "(Kalibr estimates its own IMU intrinsics)");
  return result;
}

AllanNoiseFigures AllanNoiseForKalibr(const nlohmann::json& allan, const Calibration& cal,
                                      const std::string& source) {
  if (!allan.is_object() || !allan.contains("unit") || !allan["unit"].is_string())
    throw InputError(source, 0, 0, "not an Allan analysis: no \"unit\" (\"counts\" or \"m/s^2\")");
  const std::string unit = allan["unit"].get<std::string>();
  if (unit != "counts" && unit != "m/s^2")
    throw InputError(source, 0, 0, fmt::format("unit '{}' is neither \"counts\" nor \"m/s^2\"", unit));
  if (!allan.contains("axes") || !allan["axes"].is_object())
    throw InputError(source, 0, 0, "not an Allan analysis: no \"axes\"");
  AllanNoiseFigures f;
  if (allan.contains("rate_hz") && !allan["rate_hz"].is_null()) {
    if (!allan["rate_hz"].is_number() || !PositiveFinite(allan["rate_hz"].get<double>()))
      throw InputError(source, 0, 0, "rate_hz is not a positive number");
    f.rate_hz = allan["rate_hz"].get<double>();
  }
  constexpr const char* kAxisNames[3] = {"x", "y", "z"};
  for (int j = 0; j < 3; ++j) {
    const double to_mps2 = unit == "counts" ? 1.0 / cal.model.scale_counts_per_mps2(j) : 1.0;
    const double n = AxisFigure(allan["axes"], kAxisNames[j], "noise_density", source) * to_mps2;
    const double k = AxisFigure(allan["axes"], kAxisNames[j], "random_walk", source) * to_mps2;
    if (!std::isnan(n) && !(n <= f.noise_density_mps2_per_sqrt_hz)) {
      f.noise_density_mps2_per_sqrt_hz = n;
      f.noise_density_axis = kAxisNames[j][0];
    }
    if (!std::isnan(k) && !(k <= f.random_walk_mps3_per_sqrt_hz)) {
      f.random_walk_mps3_per_sqrt_hz = k;
      f.random_walk_axis = kAxisNames[j][0];
    }
  }
  if (std::isnan(f.noise_density_mps2_per_sqrt_hz))
    throw InputError(source, 0, 0, "no axis has a noise_density");
  return f;
}

AllanNoiseFigures AllanNoiseForKalibrText(const std::string& allan_text, const Calibration& cal,
                                          const std::string& source_name) {
  return AllanNoiseForKalibr(detail::ParseJsonText(allan_text, source_name), cal, source_name);
}

}  // namespace accelcal

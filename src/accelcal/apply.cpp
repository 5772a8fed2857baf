#include "accelcal/apply.h"

#include <cmath>
#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "accelcal/detail/sample_line_parser.h"
#include "accelcal/detail/text_scan.h"

namespace accelcal {

void CheckApplicable(const Calibration& cal) {
  for (const auto& effect : cal.effects) {
    const std::string name = effect.contains("name") && effect["name"].is_string()
                                 ? effect["name"].get<std::string>()
                                 : effect.dump();
    throw Error(fmt::format("the calibration lists the effect '{}', which this version of "
                            "accelcal cannot apply", name));
  }
}

Eigen::Vector3d ApplyCalibration(const Calibration& cal, const Sample& sample) {
  return cal.model.Calibrate(sample.raw_counts);
}

ApplyStreamResult ApplyStream(std::istream& in, std::ostream& out, const Calibration& cal,
                              const std::string& source_name,
                              const std::function<void(const InputError&)>& on_error) {
  CheckApplicable(cal);
  ApplyStreamResult result;
  detail::SampleLineParser parser(source_name);
  std::string line;
  fmt::memory_buffer buffer;
  Sample sample;
  while (std::getline(in, line)) {
    ++result.lines;
    std::string_view view = line;
    if (result.lines == 1) view = detail::StripBom(view);
    if (!view.empty() && view.back() == '\r') view.remove_suffix(1);
    try {
      if (!parser.Parse(view, result.lines, &sample)) {
        if (!detail::TrimBlanks(view).empty()) out << view << '\n';
        continue;
      }
    } catch (const InputError& e) {
      ++result.malformed;
      on_error(e);
      continue;
    }
    const Eigen::Vector3d a = ApplyCalibration(cal, sample);
    buffer.clear();
    fmt::format_to(std::back_inserter(buffer), "{} {:.6f} {:.6f} {:.6f}", sample.t_s, a.x(), a.y(), a.z());
    if (std::isfinite(sample.temp_c)) fmt::format_to(std::back_inserter(buffer), " {}", sample.temp_c);
    buffer.push_back('\n');
    out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    ++result.samples;
  }
  return result;
}

}  // namespace accelcal

#include "accelcal/calibration/apply.h"

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "accelcal/base/sample_line_parser.h"
#include "accelcal/base/text_scan.h"

namespace accelcal {
namespace {

std::vector<double> EffectParameters(const Effect& effect, const CalibrationEffect& e) {
  std::vector<double> theta;
  for (int i = 0; i < effect.NumParameters(); ++i) {
    const std::string key = effect.ParameterName(i);
    const EffectParameter* p = e.Find(key);
    if (p == nullptr || !std::isfinite(p->value))
      throw Error(fmt::format("effect '{}': parameter '{}' is missing or not a finite number",
                              effect.Name(), key));
    theta.push_back(p->value);
  }
  return theta;
}

}  // namespace

CalibrationApplier::CalibrationApplier(const Calibration& cal) : model_(cal.model) {
  context_.gravity_mps2 = cal.gravity.gravity_mps2;
  for (const CalibrationEffect& e : cal.effects) {
    const std::string& name = e.name;
    const Effect* effect = FindEffect(name);
    if (effect == nullptr)
      throw Error(fmt::format("the calibration lists the effect '{}', which this version of "
                              "accelcal does not know", name));
    std::vector<double> theta = EffectParameters(*effect, e);
    if (!effect->CorrectsReadings()) {
      not_applied_.push_back(fmt::format("{} (an error of the calibration session, not of the "
                                         "sensor's readings)", name));
      continue;
    }
    if (name.rfind("temperature_", 0) == 0) {
      context_.temp_ref_c = cal.reference.temp_c;
      if (!std::isfinite(context_.temp_ref_c))
        throw Error(fmt::format("effect '{}': reference.temp_c is missing", name));
      needs_temperature_ = true;
    }
    effects_.push_back({effect, std::move(theta)});
  }
  std::stable_sort(effects_.begin(), effects_.end(), [](const AppliedEffect& a, const AppliedEffect& b) {
    return CorrectsBefore(a.effect, b.effect);
  });
}

Eigen::Vector3d CalibrationApplier::Apply(const Sample& sample) const {
  if (needs_temperature_ && !std::isfinite(sample.temp_c))
    throw Error("this calibration corrects for temperature: the line needs a temp_c field");
  FitCapture reading;
  reading.mean_counts = sample.raw_counts;
  reading.mean_temp_c = sample.temp_c;
  reading.mean_t_s = sample.t_s;
  CorrectedCapture corrected{sample.raw_counts, kNaN, 0.0};
  for (const AppliedEffect& a : effects_)
    a.effect->Correct(a.theta.data(), model_, reading, context_, &corrected);
  return model_.Calibrate(corrected.raw_counts);
}

ApplyStreamResult ApplyStream(std::istream& in, std::ostream& out, const CalibrationApplier& applier,
                              const std::string& source_name,
                              const std::function<void(const InputError&)>& on_error) {
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
    Eigen::Vector3d a;
    try {
      if (!parser.Parse(view, result.lines, &sample)) {
        if (!detail::TrimBlanks(view).empty()) out << view << '\n';
        continue;
      }
      try {
        a = applier.Apply(sample);
        // Never print inf or nan as a result (an effect's term may overflow for a wild reading).
        if (!a.allFinite()) throw Error("the calibrated value is not a finite number (the reading is out of the sensor's range)");
      } catch (const Error& e) {
        throw InputError(source_name, result.lines, 0, e.what());
      }
    } catch (const InputError& e) {
      ++result.malformed;
      on_error(e);
      continue;
    }
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

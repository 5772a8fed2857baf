#include "accelcal/calibration/apply.h"

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>

#include <fmt/format.h>

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

CalibrationApplier::CalibrationApplier(const Calibration& cal)
    : model_(cal.model), reading_unit_(cal.reading_unit) {
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
    if (effect->ReadsTemperature()) {
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

bool CalibratedLineWriter::Write(const Sample& s, std::string* why) {
  Eigen::Vector3d a;
  try {
    a = applier_.Apply(s);
    // Never print inf or nan as a result (an effect's term may overflow for a wild reading).
    if (!a.allFinite())
      throw Error("the calibrated value is not a finite number (the reading is out of the sensor's range)");
  } catch (const Error& e) {
    *why = e.what();
    return false;
  }
  line_.clear();
  fmt::format_to(std::back_inserter(line_), "{} {:.6f} {:.6f} {:.6f}", s.t_s, a.x(), a.y(), a.z());
  if (std::isfinite(s.temp_c)) fmt::format_to(std::back_inserter(line_), " {}", s.temp_c);
  line_.push_back('\n');
  out_.write(line_.data(), static_cast<std::streamsize>(line_.size()));
  return true;
}

ApplyStreamResult ApplyStream(std::istream& in, std::ostream& out, const CalibrationApplier& applier,
                              const std::string& source_name,
                              const std::function<void(const InputError&)>& on_error,
                              const SampleFormat& format, ReadingSummary* summary) {
  ApplyStreamResult result;
  SampleFormat with_unit = format;
  with_unit.unit = applier.reading_unit();
  with_unit.unit_declared = true;
  if (applier.needs_temperature())
    with_unit.require_temp_c = "this calibration corrects for temperature: the line needs a temp_c field";
  SampleReader reader(source_name, with_unit, SampleReader::OnMalformed::kSkip);
  reader.set_error_sink([&](const InputError& e) {
    ++result.malformed;
    on_error(e);
  });
  CalibratedLineWriter writer(out, applier);
  std::vector<Sample> samples;
  size_t written = 0;  // of `samples`
  // Writes the samples delivered so far (before a comment, so that it stays in place).
  const auto flush = [&] {
    std::string why;
    for (; written < samples.size(); ++written) {
      if (!writer.Write(samples[written], &why)) {
        ++result.malformed;
        on_error(InputError(source_name, reader.line_number(), 0, why));
        continue;
      }
      ++result.samples;
    }
  };
  reader.set_comment_sink([&](std::string_view comment, long) {
    flush();
    out << comment << '\n';
  });
  std::vector<char> chunk(size_t{1} << 16);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const std::streamsize got = in.gcount();
    if (got <= 0) break;
    reader.Feed(std::string_view(chunk.data(), static_cast<size_t>(got)), &samples);
    flush();
    samples.clear();
    written = 0;
  }
  reader.Finish(&samples);
  flush();
  result.lines = reader.line_number();
  if (summary != nullptr) *summary = reader.Summary();
  return result;
}

}  // namespace accelcal

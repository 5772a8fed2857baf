// Applying a calibration to raw samples: a^p = T K^-1 (raw' - b), m/s^2 (sensor_model.h), where
// raw' is the reading with the calibration's sensor effects removed (quadratic nonlinearity,
// temperature effects; effect.h). Effects of the bench during calibration (radius, speed, size
// effect) and the session's bias drift are not properties of later readings: they are listed
// in the file for the record and not applied.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/base/error.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/base/sample_reader.h"
#include "accelcal/calibration/calibration.h"

namespace accelcal {

class CalibrationApplier {
 public:
  // Throws accelcal::Error for an effect this version does not know or whose parameters are
  // malformed: applying the base model alone would give silently wrong numbers.
  explicit CalibrationApplier(const Calibration& cal);

  // What the readings must be in (the calibration's): counts, or a logger's m/s^2 or g, which
  // the reader converts to the calibration's counts (sample_format.h).
  const ReadingUnit& reading_unit() const { return reading_unit_; }
  // True when an applied effect depends on temperature (readings must carry temp_c).
  bool needs_temperature() const { return needs_temperature_; }
  // Effects listed in the file but not applied to readings, with why (for the user).
  const std::vector<std::string>& not_applied() const { return not_applied_; }

  // The calibrated specific force of one reading, m/s^2 (platform frame). Throws
  // accelcal::Error when the sample lacks a temperature the calibration needs.
  Eigen::Vector3d Apply(const Sample& sample) const;

 private:
  struct AppliedEffect {
    const Effect* effect;  // static, from AllEffects()
    std::vector<double> theta;
  };
  SensorModel model_;
  ReadingUnit reading_unit_;
  EffectContext context_;
  std::vector<AppliedEffect> effects_;
  std::vector<std::string> not_applied_;
  bool needs_temperature_ = false;
};

// Writes calibrated samples as the lines `apply` prints: `t ax ay az [temp_c]`, ax ay az the
// calibrated a^p in m/s^2 with 6 decimals. A reading whose calibrated value cannot be given (it
// lacks the temperature the calibration needs, or the value is not finite: no inf or nan is
// ever written) is not written.
class CalibratedLineWriter {
 public:
  CalibratedLineWriter(std::ostream& out, const CalibrationApplier& applier)
      : out_(out), applier_(applier) {}
  // Writes one sample's line; false with *why (in words) when it cannot be given.
  bool Write(const Sample& sample, std::string* why);

 private:
  std::ostream& out_;
  const CalibrationApplier& applier_;
  std::string line_;
};

struct ApplyStreamResult {
  long lines = 0;      // lines read
  long samples = 0;    // data lines written calibrated
  long malformed = 0;  // lines reported to on_error and skipped
};

// Reads samples from `in` with the one sample reader (base/sample_reader.h: the protocol's
// `t ax ay az [temp_c]`, or the columns, header, skipped rows and rate `format` gives; the
// readings' unit is the calibration's) and writes `t ax ay az [temp_c]` with ax ay az in m/s^2
// to `out`; comments are passed through. A malformed line (or one without the temperature the
// calibration needs) goes to `on_error` and is skipped; the stream goes on. So is a line whose
// calibrated value is not finite: no inf or nan is ever written. *summary (when not null) gets
// what the reading understood.
ApplyStreamResult ApplyStream(std::istream& in, std::ostream& out, const CalibrationApplier& applier,
                              const std::string& source_name,
                              const std::function<void(const InputError&)>& on_error,
                              const SampleFormat& format = {}, ReadingSummary* summary = nullptr);

}  // namespace accelcal

// Effects that the seed's nine-parameter model lacks, each with a physical story, a
// parameterization, and the data it needs to be identifiable. The diagnosis (diagnosis.h) adds
// them to the model one at a time when the residuals call for it.
//
// How an effect enters the fit: for each capture it corrects the mean raw reading into what the
// base model (sensor_model.h) should see, and/or the reference magnitude |f| the capture should
// show. The residual stays r = |T K^-1 (raw' - b)| - |f'|, in m/s^2.
//
// Reference points: temperatures are taken relative to `temp_ref_c` and times relative to
// `t_ref_s`, the means over the captures used in the fit, so the base bias and scale stay those
// of the session's typical conditions.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "accelcal/calibration/diagnosis/bench_statement.h"
#include "accelcal/calibration/diagnosis/c_correction.h"
#include "accelcal/calibration/diagnosis/effect_jet.h"
#include "accelcal/calibration/fit/fit_capture.h"
#include "accelcal/base/sensor_model.h"

namespace accelcal {

struct EffectContext {
  double gravity_mps2 = 9.80665;
  double temp_ref_c = 0.0;  // mean temperature of the captures used, degC
  double t_ref_s = 0.0;     // mean time of the captures used, s
};

class Effect {
 public:
  virtual ~Effect() = default;

  // Stable name, as in the calibration file ("quadratic_nonlinearity", ...).
  virtual std::string_view Name() const = 0;
  // One sentence: the physical story.
  virtual std::string_view Story() const = 0;
  virtual int NumParameters() const = 0;
  virtual std::string ParameterName(int i) const = 0;  // e.g. "q_x"
  virtual std::string ParameterUnit(int i) const = 0;  // e.g. "counts/(m/s^2)^2"
  // A parameter change that moves a typical residual by ~1e-3 m/s^2 (optimizer scaling only).
  virtual double ParameterScale(int i, const SensorModel& base, const EffectContext& ctx) const = 0;
  // Empty when the captures can identify the effect; otherwise why not, in words.
  virtual std::string WhyNotIdentifiable(const std::vector<FitCapture>& captures) const = 0;
  // The captures that identify it, in words (docs/model.md's effects table; what to capture next).
  virtual std::string_view CapturePlan() const = 0;
  // Empty when parameters `theta` are physically plausible for a bench calibration (the
  // datasheet's or the procedure's bounds, stated in the message), given the base model and the
  // captures they were fitted to; otherwise why not, in words. An effect whose fitted size no
  // sensor or bench could have is a wrong explanation, however well it fits.
  virtual std::string WhyImplausible(const double* theta, const SensorModel& base,
                                     const std::vector<FitCapture>& captures) const = 0;
  // Applies the effect with parameters `theta` (NumParameters() values) to capture `c`.
  virtual void Correct(const double* theta, const SensorModel& base, const FitCapture& c,
                       const EffectContext& ctx, CorrectedCapture* out) const = 0;
  // The same correction carrying derivatives (effect_jet.h): `theta`, `base` and `out` hold
  // jets over b, K and the effects' parameters. False when the effect has no such form (the default): the
  // fit then differentiates the whole residual by central differences.
  virtual bool CorrectJet(const EffectJet* /*theta*/, const JetBiasAndScale& /*base*/,
                          const FitCapture& /*c*/, const EffectContext& /*ctx*/,
                          CorrectedCaptureOf<EffectJet>* /*out*/) const {
    return false;
  }
  // The physical variable the effect grows with, for the evidence in words ("temperature",
  // "w^2 r", ...), and its value for a capture (NaN where it does not apply). Empty name: none
  // (the quadratic depends on each axis's input, not on one variable).
  virtual std::string_view RegressorName() const { return {}; }
  // What parameters `theta` mean in the bench's terms, when that differs from the parameters
  // themselves ("a spin axis tilted 2.00 deg from the vertical"); empty otherwise.
  virtual std::string Interpretation(const double*) const { return {}; }
  virtual double Regressor(const FitCapture&) const { return kNaN; }
  // Corrections run in stage order, inverting the forward model from the outside in:
  // 0 additive shifts of the reading (temperature bias, drift), 1 scale changes, 2 the
  // nonlinearity (solved on the shifted, rescaled reading), 3 the bench's geometry.
  virtual int CorrectionStage() const = 0;
  // True for properties of the sensor itself, which `accelcal apply` corrects in every reading;
  // false for errors of the bench during calibration (radius, speed), which it does not.
  virtual bool CorrectsReadings() const = 0;
  // True when its correction reads the sensor's temperature (a capture's mean_temp_c, a
  // reading's temp_c, relative to the context's temp_ref_c): `accelcal apply` then needs a
  // temperature on every reading, and the C header's function takes one.
  virtual bool ReadsTemperature() const { return false; }

  // --- What the technician is told of it (bench_statement.h; app/wizard/diagnosis_words.h) ---
  // Its name in the bench's words, lower case ("a wrong turntable radius"); empty (the
  // default): Name() is said.
  virtual std::string_view PlainName() const { return {}; }
  // True for an error of the bench during the calibration (radius, speed, tilt): the advice is
  // to correct it and refit; false for the sensor's own: to add it to the calibration.
  virtual bool IsBenchError() const { return false; }
  // What fitted parameters `values` (with their 1-sigma `sigmas`, and Interpretation() of them
  // `interpretation`) mean at the bench, its size in bench units; `gravity_mps2` sizes a
  // response at 1 g. None (the default, or values that make no statement): its name and
  // parameters are said instead.
  virtual std::optional<BenchStatement> InBenchTerms(std::span<const double> /*values*/,
                                                     std::span<const double> /*sigmas*/,
                                                     std::string_view /*interpretation*/,
                                                     double /*gravity_mps2*/) const {
    return std::nullopt;
  }

  // --- What the report says of it (report/report_model.h) ----------------------------------
  // What a magnitude fit cannot resolve of it, said beside the nine parameters when it is
  // adopted (one sentence, after its name); empty (the default): nothing.
  virtual std::string_view ReportNote() const { return {}; }
  // True when the captures see its size only through w^2 r / g (a speed or radius scale): an
  // error of the gravity value looks the same, and while gravity is the standard value the
  // report says so and the verdict cannot be PASS.
  virtual bool TakesGravityErrorForItsOwn() const { return false; }
  // For an effect that is an error of a bench quantity an item of the lab's equipment verifies
  // (the radius, the table's speed): that item, by its name in the procedure's [equipment]
  // ("ruler", "turntable": session/equipment.h's table), what of the turntable it verifies
  // ("radius", "speed") and what checks it again ("a calibrated ruler"). Its first parameter is
  // that quantity's error in SI (m, a fraction); the report sets it against the item's stated
  // uncertainty. nullopt (the default): no item verifies it.
  struct VerifyingEquipment {
    std::string_view item;
    std::string_view quantity;
    std::string_view checked_with;
  };
  virtual std::optional<VerifyingEquipment> VerifiedBy() const { return std::nullopt; }

  // --- How each export carries it (io/export/) ----------------------------------------------
  // Every export writes its parameters (CSV) and says what it cannot hold; a session's effect
  // (CorrectsReadings false) is never carried (a note says so), nor by a per-axis offset and
  // scale (ArduPilot, PX4) any effect. A sensor's effect in the C header: its C form
  // (c_correction.h); without one (the default), the header refuses the calibration, naming it.
  virtual std::optional<CCorrection> InC() const { return std::nullopt; }
};

// An effect whose correction is written once, as
//   template <class S, class Base> void Apply(const S* theta, const Base& base,
//       const FitCapture& c, const EffectContext& ctx, CorrectedCaptureOf<S>* out) const;
// (S double with Base SensorModel, or S EffectJet with Base JetBiasAndScale; base gives
// bias_counts(j) and scale_counts_per_mps2(j)); this gives Effect both corrections from it.
template <class Derived>
class DifferentiableEffect : public Effect {
 public:
  void Correct(const double* theta, const SensorModel& base, const FitCapture& c,
               const EffectContext& ctx, CorrectedCapture* out) const final {
    static_cast<const Derived*>(this)->Apply(theta, base, c, ctx, out);
  }
  bool CorrectJet(const EffectJet* theta, const JetBiasAndScale& base, const FitCapture& c,
                  const EffectContext& ctx, CorrectedCaptureOf<EffectJet>* out) const final {
    static_cast<const Derived*>(this)->Apply(theta, base, c, ctx, out);
    return true;
  }
};

// True when `a` corrects before `b` (an earlier CorrectionStage).
inline bool CorrectsBefore(const Effect* a, const Effect* b) {
  return a->CorrectionStage() < b->CorrectionStage();
}

// `effects` sorted by CorrectsBefore (stable): the order in which corrections are applied.
std::vector<const Effect*> InCorrectionOrder(std::vector<const Effect*> effects);

// A parameter's unit as printed after its value: empty for a dimensionless one ("1"), so a
// line reads "rpm_scale = 0.00136 +- 4.4e-05", never "... 4.4e-05 1".
inline std::string_view UnitAfterValue(std::string_view unit) { return unit == "1" ? std::string_view() : unit; }

// The library, in a fixed order: the effects the diagnosis tries. Ownership: the returned effects
// are static; never freed.
const std::vector<const Effect*>& AllEffects();
// Every effect known by name: the library's, then the registered ones (EffectRegistration) in
// the order registered.
std::vector<const Effect*> KnownEffects();
// The known effect of that name; nullptr when there is none.
const Effect* FindEffect(std::string_view name);

// Makes `effect`, defined outside the library (a test's), known by name while the registration
// lives: a calibration that lists it is read, applied, put in words, reported and exported as
// one of the library's (each of those asks the effect, never its name). The diagnosis tries only
// the library's. `effect` must outlive the registration. Throws accelcal::Error when a known
// effect already has its name.
class EffectRegistration {
 public:
  explicit EffectRegistration(const Effect& effect);
  ~EffectRegistration();
  EffectRegistration(const EffectRegistration&) = delete;
  EffectRegistration& operator=(const EffectRegistration&) = delete;

 private:
  const Effect* effect_;
};

}  // namespace accelcal

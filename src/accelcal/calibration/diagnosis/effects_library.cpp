// The library of effects (effect.h): its fixed order, and the helpers its effects share
// (effect_support.h). The effects themselves: sensor_effects.cpp (properties of the sensor),
// bench_effects.cpp (errors of the bench during the calibration).
#include <algorithm>
#include <cmath>
#include <mutex>

#include <fmt/core.h>

#include "accelcal/base/error.h"
#include "accelcal/base/linear_algebra.h"
#include "accelcal/calibration/diagnosis/effect_support.h"

namespace accelcal {
namespace effects {
namespace {

template <typename Get>
double Spread(const std::vector<FitCapture>& captures, Get get) {
  double lo = INFINITY, hi = -INFINITY;
  for (const FitCapture& c : captures) {
    const double v = get(c);
    if (!std::isfinite(v)) return NAN;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return hi - lo;
}

}  // namespace

std::string PerAxis(const char* stem, int axis) { return fmt::format("{}_{}", stem, "xyz"[axis]); }

std::vector<std::string> PerAxisNames(const char* stem) { return {PerAxis(stem, 0), PerAxis(stem, 1), PerAxis(stem, 2)}; }

double FirstOf(std::span<const double> values) { return values.empty() ? kNaN : values.front(); }

BenchStatement PerAxisStatement(std::string lead, std::span<const double> values, double factor, int decimals,
                                std::string unit) {
  BenchStatement s;
  s.lead = std::move(lead);
  s.size.shape = BenchQuantity::Shape::kPerAxis;
  for (double v : values) s.size.values.push_back(v * factor);
  s.size.unit = std::move(unit);
  s.size.decimals = decimals;
  return s;
}

int CountTurntable(const std::vector<FitCapture>& captures) {
  int n = 0;
  for (const FitCapture& c : captures) n += c.kind == CaptureKind::kTurntable;
  return n;
}

int CountDistinctRadii(const std::vector<FitCapture>& captures) {
  std::vector<double> radii;
  for (const FitCapture& c : captures) {
    if (c.kind != CaptureKind::kTurntable) continue;
    bool seen = false;
    for (double r : radii) seen |= std::fabs(r - c.radius_m) < 1e-4;
    if (!seen) radii.push_back(c.radius_m);
  }
  return static_cast<int>(radii.size());
}

double SpreadOfTemperature(const std::vector<FitCapture>& captures) {
  return Spread(captures, [](const FitCapture& c) { return c.mean_temp_c; });
}

double SpreadOfTime(const std::vector<FitCapture>& captures) {
  return Spread(captures, [](const FitCapture& c) { return c.mean_t_s; });
}

bool SeesLevelsFor(const std::vector<FitCapture>& captures, int j, int power) {
  double lo = INFINITY, hi = -INFINITY;
  for (const FitCapture& c : captures) {
    lo = std::min(lo, c.mean_counts(j));
    hi = std::max(hi, c.mean_counts(j));
  }
  if (!(hi > lo)) return false;
  std::vector<double> xs;
  for (const FitCapture& c : captures) {
    const double x = (2.0 * c.mean_counts(j) - lo - hi) / (hi - lo);
    if (std::fabs(x) > 0.2) xs.push_back(x);
  }
  if (xs.size() < 3) return false;
  Eigen::MatrixXd design(xs.size(), 3);
  for (size_t i = 0; i < xs.size(); ++i) design.row(i) << 1.0, xs[i], std::pow(xs[i], power);
  for (int k = 0; k < 3; ++k) design.col(k).normalize();
  const Eigen::VectorXd sv = SingularValues(design);
  return sv(2) > 0.05 * sv(0);
}

std::vector<Eigen::Vector3d> Inputs(const std::vector<FitCapture>& captures, const SensorModel& base) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(captures.size());
  for (const FitCapture& c : captures)
    out.push_back((c.mean_counts - base.bias_counts).cwiseQuotient(base.scale_counts_per_mps2));
  return out;
}

std::vector<Eigen::Vector3d> RoughDirections(const std::vector<FitCapture>& captures) {
  int statics = 0;
  for (const FitCapture& c : captures) statics += c.kind == CaptureKind::kStatic;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const FitCapture& c : captures) {
    if (statics >= 2 && c.kind != CaptureKind::kStatic) continue;
    lo = lo.cwiseMin(c.mean_counts);
    hi = hi.cwiseMax(c.mean_counts);
  }
  const Eigen::Vector3d mid = 0.5 * (lo + hi);
  const Eigen::Vector3d half = (0.5 * (hi - lo)).cwiseMax(1e-9);
  std::vector<Eigen::Vector3d> out;
  for (const FitCapture& c : captures) {
    const Eigen::Vector3d d = (c.mean_counts - mid).cwiseQuotient(half);
    out.push_back(d.norm() > 0.0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::Zero());
  }
  return out;
}

double CentripetalMps2(const FitCapture& c) {
  if (c.kind != CaptureKind::kTurntable) return kNaN;
  const double w = RpmToRadPerS(c.rpm);
  return w * w * c.radius_m;
}

// The library's effects, each a static object (never freed), defined beside its class: the
// sensor's in sensor_effects.cpp, the bench's in bench_effects.cpp. A new effect is declared
// here and listed below, and nowhere else (ARCHITECTURE.md, "How to add an effect").
const Effect& QuadraticNonlinearityEffect();
const Effect& CubicNonlinearityEffect();
const Effect& CrossAxisCouplingEffect();
const Effect& TemperatureBiasEffect();
const Effect& TemperatureScaleEffect();
const Effect& BiasDriftEffect();
const Effect& RadiusOffsetEffect();
const Effect& RpmScaleEffect();
const Effect& SizeEffectEffect();
const Effect& TurntableTiltEffect();

}  // namespace effects

const std::vector<const Effect*>& AllEffects() {
  using namespace effects;
  static const std::vector<const Effect*> all = {
      &QuadraticNonlinearityEffect(), &CubicNonlinearityEffect(), &CrossAxisCouplingEffect(),
      &TemperatureBiasEffect(),       &TemperatureScaleEffect(),  &BiasDriftEffect(),
      &RadiusOffsetEffect(),          &RpmScaleEffect(),          &SizeEffectEffect(),
      &TurntableTiltEffect()};
  return all;
}

std::vector<const Effect*> InCorrectionOrder(std::vector<const Effect*> effects) {
  std::stable_sort(effects.begin(), effects.end(), CorrectsBefore);
  return effects;
}

namespace {

// The effects registered from outside the library (EffectRegistration), under their lock.
std::mutex& RegisteredEffectsMutex() {
  static std::mutex mutex;
  return mutex;
}
std::vector<const Effect*>& RegisteredEffects() {
  static std::vector<const Effect*> registered;
  return registered;
}

const Effect* FindIn(const std::vector<const Effect*>& effects, std::string_view name) {
  for (const Effect* e : effects)
    if (e->Name() == name) return e;
  return nullptr;
}

}  // namespace

std::vector<const Effect*> KnownEffects() {
  std::vector<const Effect*> known = AllEffects();
  const std::lock_guard<std::mutex> lock(RegisteredEffectsMutex());
  known.insert(known.end(), RegisteredEffects().begin(), RegisteredEffects().end());
  return known;
}

const Effect* FindEffect(std::string_view name) {
  if (const Effect* e = FindIn(AllEffects(), name)) return e;
  const std::lock_guard<std::mutex> lock(RegisteredEffectsMutex());
  return FindIn(RegisteredEffects(), name);
}

EffectRegistration::EffectRegistration(const Effect& effect) : effect_(&effect) {
  const std::lock_guard<std::mutex> lock(RegisteredEffectsMutex());
  if (FindIn(AllEffects(), effect.Name()) != nullptr || FindIn(RegisteredEffects(), effect.Name()) != nullptr)
    throw Error(fmt::format("an effect named '{}' is already known", effect.Name()));
  RegisteredEffects().push_back(effect_);
}

EffectRegistration::~EffectRegistration() {
  const std::lock_guard<std::mutex> lock(RegisteredEffectsMutex());
  std::vector<const Effect*>& registered = RegisteredEffects();
  registered.erase(std::remove(registered.begin(), registered.end(), effect_), registered.end());
}

}  // namespace accelcal

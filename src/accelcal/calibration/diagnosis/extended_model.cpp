#include "accelcal/calibration/diagnosis/extended_model.h"

#include <algorithm>
#include <cmath>

namespace accelcal {
namespace {

// The capture as read, before any correction, each value made a double or a jet by `lift`.
template <class S, class Lift>
CorrectedCaptureOf<S> Uncorrected(const FitCapture& c, Lift lift) {
  return {{lift(c.mean_counts(0)), lift(c.mean_counts(1)), lift(c.mean_counts(2))},
          lift(c.radius_m),
          lift(c.kind == CaptureKind::kTurntable ? RpmToRadPerS(c.rpm) : 0.0),
          lift(1.0)};
}

double Hypot(double a, double b) { return std::hypot(a, b); }
// The jet's value exactly the double's; its derivatives those of sqrt(a^2 + b^2).
EffectJet Hypot(const EffectJet& a, const EffectJet& b) {
  EffectJet h = sqrt(a * a + b * b);
  h.value() = std::hypot(a.value(), b.value());
  return h;
}

// |f'| of a corrected turntable capture, sqrt((g along the spin axis)^2 + (w^2 r)^2) (a static
// capture's is g).
template <class S>
S TurntableReference(const CorrectedCaptureOf<S>& cc, double gravity_mps2) {
  return Hypot(gravity_mps2 * cc.gravity_along_axis,
               cc.omega_rad_per_s * cc.omega_rad_per_s * cc.radius_m);
}

}  // namespace

ExtendedResidualModel::ExtendedResidualModel(std::vector<const Effect*> effects,
                                             EffectContext context)
    : effects_(std::move(effects)), context_(context) {
  for (const Effect* e : effects_) {
    offsets_.push_back(num_parameters_);
    num_parameters_ += e->NumParameters();
  }
  for (const Effect* e : InCorrectionOrder(effects_))
    correction_order_.push_back(static_cast<int>(std::find(effects_.begin(), effects_.end(), e) - effects_.begin()));
}

std::string ExtendedResidualModel::ParameterLabel(int i) const {
  if (i < kNumBaseParameters) return std::string(ParameterName(i));
  for (size_t e = effects_.size(); e-- > 0;)
    if (i >= offsets_[e]) return effects_[e]->ParameterName(i - offsets_[e]);
  return "?";
}

double ExtendedResidualModel::ParameterScale(const Eigen::VectorXd& p, int i) const {
  static const BaseResidualModel kBase;
  if (i < kNumBaseParameters) return kBase.ParameterScale(p, i);
  const SensorModel base = SensorModel::FromVector(p.head(kNumBaseParameters));
  for (size_t e = effects_.size(); e-- > 0;)
    if (i >= offsets_[e]) return effects_[e]->ParameterScale(i - offsets_[e], base, context_);
  return 1.0;
}

CorrectedCapture ExtendedResidualModel::Corrected(const Eigen::VectorXd& p,
                                                  const FitCapture& c) const {
  const SensorModel base = SensorModel::FromVector(p.head(kNumBaseParameters));
  CorrectedCapture out = Uncorrected<double>(c, [](double v) { return v; });
  for (int e : correction_order_) effects_[e]->Correct(p.data() + offsets_[e], base, c, context_, &out);
  return out;
}

double ExtendedResidualModel::Value(const Eigen::VectorXd& p, const FitCapture& c,
                                    double gravity_mps2) const {
  const CorrectedCapture cc = Corrected(p, c);
  const double reference =
      c.kind == CaptureKind::kTurntable ? TurntableReference(cc, gravity_mps2) : gravity_mps2;
  return CalibratedMagnitude(p, cc.raw_counts, nullptr, nullptr) - reference;
}

double ExtendedResidualModel::Residual(const Eigen::VectorXd& p, const FitCapture& c,
                                       double gravity_mps2, Eigen::VectorXd* grad_p,
                                       Eigen::Vector3d* grad_raw) const {
  double r = 0.0;
  if (grad_p == nullptr || !JetResidual(p, c, gravity_mps2, &r, grad_p)) {
    r = Value(p, c, gravity_mps2);
    if (grad_p != nullptr) NumericGradient(p, c, gravity_mps2, grad_p);
  }
  if (grad_raw != nullptr) {
    // The effects change the reading by small fractions: the base model's sensitivity at the
    // corrected reading is the uncertainty propagation's gradient to well under 1 %.
    CalibratedMagnitude(p, Corrected(p, c).raw_counts, nullptr, grad_raw);
  }
  return r;
}

bool ExtendedResidualModel::JetCorrected(const Eigen::VectorXd& p, const FitCapture& c,
                                         CorrectedCaptureOf<EffectJet>* cc) const {
  static_assert(kBiasX == 0 && kScaleX == 3 && kJetBaseSlots == 6, "b and K lead ParameterIndex");
  const int effect_parameters = num_parameters_ - kNumBaseParameters;
  if (kJetBaseSlots + effect_parameters > kMaxJetParameters) return false;
  using Derivatives = EffectJet::DerType;
  const auto parameter = [&](int i, int slot) { return EffectJet(p(i), Derivatives::Unit(slot)); };
  JetBiasAndScale base;
  for (int j = 0; j < 3; ++j) {
    base.bias_counts(j) = parameter(kBiasX + j, kBiasX + j);
    base.scale_counts_per_mps2(j) = parameter(kScaleX + j, kScaleX + j);
  }
  EffectJet theta[kMaxJetParameters];  // the effects' parameters, in slots from kJetBaseSlots
  for (int i = 0; i < effect_parameters; ++i)
    theta[i] = parameter(kNumBaseParameters + i, kJetBaseSlots + i);
  for (int e : correction_order_)
    if (!effects_[e]->CorrectJet(theta + (offsets_[e] - kNumBaseParameters), base, c, context_, cc))
      return false;
  return true;
}

bool ExtendedResidualModel::JetResidual(const Eigen::VectorXd& p, const FitCapture& c,
                                        double gravity_mps2, double* r,
                                        Eigen::VectorXd* grad_p) const {
  CorrectedCaptureOf<EffectJet> cc =
      Uncorrected<EffectJet>(c, [](double v) { return EffectJet(v, EffectJet::DerType::Zero()); });
  if (!JetCorrected(p, c, &cc)) return false;
  // r = |T K^-1 (raw' - b)| - |f'|: the base magnitude's own analytic gradient at the corrected
  // reading, plus its sensitivity to the reading times the reading's derivatives, less the
  // reference's derivatives. The values are those of Corrected and Value (the same operations
  // on the same doubles), so r is Value's.
  const Eigen::Vector3d raw(cc.raw_counts(0).value(), cc.raw_counts(1).value(),
                            cc.raw_counts(2).value());
  Eigen::VectorXd grad_base(kNumBaseParameters);
  Eigen::Vector3d grad_raw;
  *r = CalibratedMagnitude(p, raw, &grad_base, &grad_raw);
  EffectJet::DerType slots = EffectJet::DerType::Zero();
  slots.head(kJetBaseSlots) = grad_base.head(kJetBaseSlots);
  for (int j = 0; j < 3; ++j) slots += grad_raw(j) * cc.raw_counts(j).derivatives();
  if (c.kind == CaptureKind::kTurntable) {
    const EffectJet reference = TurntableReference(cc, gravity_mps2);
    *r -= reference.value();
    slots -= reference.derivatives();
  } else {
    *r -= gravity_mps2;
  }
  const int effect_parameters = num_parameters_ - kNumBaseParameters;
  Eigen::VectorXd& grad = *grad_p;
  grad.resize(num_parameters_);
  grad.head(kJetBaseSlots) = slots.head(kJetBaseSlots);
  grad.segment(kJetBaseSlots, kNumBaseParameters - kJetBaseSlots) =
      grad_base.tail(kNumBaseParameters - kJetBaseSlots);
  grad.tail(effect_parameters) = slots.segment(kJetBaseSlots, effect_parameters);
  return true;
}

void ExtendedResidualModel::NumericGradient(const Eigen::VectorXd& p, const FitCapture& c,
                                            double gravity_mps2, Eigen::VectorXd* grad_p) const {
  grad_p->resize(num_parameters_);
  Eigen::VectorXd q = p;
  for (int i = 0; i < num_parameters_; ++i) {
    const double h = 1e-3 * ParameterScale(p, i);
    q(i) = p(i) + h;
    const double up = Value(q, c, gravity_mps2);
    q(i) = p(i) - h;
    const double down = Value(q, c, gravity_mps2);
    q(i) = p(i);
    (*grad_p)(i) = (up - down) / (2.0 * h);
  }
}

EffectContext MakeEffectContext(const std::vector<FitCapture>& captures, double gravity_mps2) {
  EffectContext ctx;
  ctx.gravity_mps2 = gravity_mps2;
  double t_sum = 0, temp_sum = 0;
  int t_n = 0, temp_n = 0;
  for (const FitCapture& c : captures) {
    if (std::isfinite(c.mean_t_s)) { t_sum += c.mean_t_s; ++t_n; }
    if (std::isfinite(c.mean_temp_c)) { temp_sum += c.mean_temp_c; ++temp_n; }
  }
  ctx.t_ref_s = t_n > 0 ? t_sum / t_n : 0.0;
  ctx.temp_ref_c = temp_n > 0 ? temp_sum / temp_n : 0.0;
  return ctx;
}

}  // namespace accelcal

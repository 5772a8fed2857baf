// The seed's model plus effects (effect.h), as a ResidualModel for the least-squares solver.
//
// Parameters: the nine base ones (ParameterIndex order) followed by each effect's, in the order
// the effects were given. The Jacobian is exact, carried through the effects' corrections as
// jets (effect_jet.h); an effect without that form makes it central differences, with steps of
// 1e-3 of each parameter's scale.
#pragma once

#include <string>
#include <vector>

#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/calibration/fit/residual_model.h"

namespace accelcal {

class ExtendedResidualModel final : public ResidualModel {
 public:
  // `effects` are borrowed from AllEffects() (static). `context` gives the reference
  // temperature and time.
  ExtendedResidualModel(std::vector<const Effect*> effects, EffectContext context);

  int NumParameters() const override { return num_parameters_; }
  std::string ParameterLabel(int i) const override;
  double ParameterScale(const Eigen::VectorXd& p, int i) const override;
  double Residual(const Eigen::VectorXd& p, const FitCapture& c, double gravity_mps2,
                  Eigen::VectorXd* grad_p, Eigen::Vector3d* grad_raw) const override;

  const std::vector<const Effect*>& effects() const { return effects_; }
  // Index of the first parameter of effect `e` (0-based among effects()).
  int Offset(int e) const { return offsets_[e]; }
  const EffectContext& context() const { return context_; }

  // The capture as the base model sees it with all effects applied at p.
  CorrectedCapture Corrected(const Eigen::VectorXd& p, const FitCapture& c) const;

 private:
  double Value(const Eigen::VectorXd& p, const FitCapture& c, double gravity_mps2) const;
  // Corrects *cc (the capture as read, as jets) with derivatives (effect_jet.h); false when an
  // effect has no jets or the model has too many parameters for them.
  bool JetCorrected(const Eigen::VectorXd& p, const FitCapture& c,
                    CorrectedCaptureOf<EffectJet>* cc) const;
  // r and dr/dp through the effects' jets; r is the same as Value's. False as JetCorrected.
  bool JetResidual(const Eigen::VectorXd& p, const FitCapture& c, double gravity_mps2,
                   double* r, Eigen::VectorXd* grad_p) const;
  // dr/dp by central differences, steps of 1e-3 of each parameter's scale.
  void NumericGradient(const Eigen::VectorXd& p, const FitCapture& c, double gravity_mps2,
                       Eigen::VectorXd* grad_p) const;

  std::vector<const Effect*> effects_;
  std::vector<int> offsets_;
  std::vector<int> correction_order_;  // indices into effects_, by CorrectionStage
  int num_parameters_ = kNumBaseParameters;
  EffectContext context_;
};

// Reference temperature and time: the means over `captures` (NaN-free ones for temperature).
EffectContext MakeEffectContext(const std::vector<FitCapture>& captures, double gravity_mps2);

}  // namespace accelcal

// The effects' corrections with derivatives (forward-mode automatic differentiation, Eigen's
// AutoDiffScalar): the extended fit's Jacobian in one pass per capture instead of two
// evaluations per parameter by central differences (issue 18: those were 70 % of a fit with
// the diagnosis).
//
// An effect writes its correction once, as a template over the scalar (`double` for values,
// `EffectJet` for values with their derivatives), and derives from DifferentiableEffect, which
// turns that template into both of Effect's corrections.
#pragma once

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace accelcal {

// What the jets differentiate with respect to: the base model's bias and scale (b_x, b_y, b_z,
// k_x, k_y, k_z, the first six of ParameterIndex), then the effects' parameters in the model's
// order. The misalignment angles act only in the base magnitude, whose own gradient is analytic
// (CalibratedMagnitude), so the jets do not carry them.
inline constexpr int kJetBaseSlots = 6;
// The slots of a jet, fixed (a model with more than 10 effect parameters falls back to central
// differences): fixed-size derivatives cost no size checks or loops of unknown length.
inline constexpr int kMaxJetParameters = 16;

// A value and its derivatives with respect to those parameters (unused slots stay zero).
using EffectJet = Eigen::AutoDiffScalar<Eigen::Matrix<double, kMaxJetParameters, 1>>;

inline double ValueOf(double x) { return x; }
inline double ValueOf(const EffectJet& x) { return x.value(); }

// What a capture becomes once an effect is accounted for (S: double, or EffectJet).
template <class S>
struct CorrectedCaptureOf {
  Eigen::Matrix<S, 3, 1> raw_counts;  // the mean reading as the base model should see it
  S radius_m;                         // turntable: the radius the reference should use
  S omega_rad_per_s;                  // turntable: the speed the reference should use
  // Turntable: the fraction of gravity along the spin axis the reference should use,
  // |f| = sqrt((g along)^2 + (w^2 r)^2); 1 for a level table.
  S gravity_along_axis = S(1.0);
};
using CorrectedCapture = CorrectedCaptureOf<double>;

// The part of the base model the corrections use, with derivatives: b and K (SensorModel's
// members of the same names serve the double case).
struct JetBiasAndScale {
  Eigen::Matrix<EffectJet, 3, 1> bias_counts;
  Eigen::Matrix<EffectJet, 3, 1> scale_counts_per_mps2;
};

}  // namespace accelcal

// Closing the loop: when a fit's residuals are larger than the captures' noise explains, find
// which effect (effect.h) the model lacks, add it, and report the error before and after.
//
//  1. Consistency: chi2 = sum (r_i / sigma_i)^2 against the chi-square distribution with
//     n - k degrees of freedom; p >= consistency_p means the residuals are what noise explains:
//     stop.
//  2. Candidates: every effect of the library not yet adopted is checked for identifiability
//     (skipped with its reason otherwise), added to the current model and refitted, and scored:
//     BIC = chi2 + k ln n (chi2 divided by max(1, chi2/dof) of the candidate's own fit, so that
//     a partial explanation is not ranked on noise it cannot explain), AICc, the likelihood-ratio
//     test against the current model, and the leave-one-capture-out prediction (LOO,
//     leave_one_out.h). The ranking is by BIC.
//  3. Adoption: the best-ranked candidate that passes every test below is adopted:
//     - significant: a likelihood-ratio test, delta chi2 over m added parameters, with delta
//       chi2 divided by max(1, chi2/dof after) so that noise underestimated by the captures' own
//       statistics does not make everything look significant, Bonferroni-corrected for the
//       number of candidates tried (p * candidates < adoption_p);
//     - it predicts the captures it did not see, judged against noise: the worst LOO z (its
//       prediction error over its noise-only sigma, scaled by sqrt(max(1, chi2/dof after))) is
//       not beyond what n normals give (family p >= prediction_p);
//     - its parameters are physically plausible (Effect::WhyImplausible: datasheet or bench
//       bounds);
//     - among candidates that pass and imply different calibrations (exactly one of them
//       corrects later readings, or their nine parameters differ by more than 2 combined
//       sigma), one within 6 of the best BIC ("strong" on the Kass & Raftery scale) but 2 or
//       more from it is decided by the prediction of the left-out captures (the smaller LOO
//       RMS wins: a drift in time and a temperature warm-up can fit alike, the right one
//       predicts the first and last poses better); two within 2 of each other cannot be told
//       apart by these captures: neither is adopted, and both are named;
//     - it beats the rival explanations outside the library that challenge its correction
//       stage (rival_explanations.h) by a BIC 6 or more; otherwise it is not adopted, and it and
//       the rival are named (`ambiguous`) with what to capture to tell them apart.
//     A candidate that fits but fails a test is named with the reason. Then back to 1.
//  4. The adopted set must explain the residuals: the final model's residuals are what noise
//     explains (chi-square p >= consistency_p), show no structure in pose or time
//     (residual_structure.h, family p >= structure_p), and predict every capture from the
//     others within noise (LOO unscaled, family p >= prediction_p). Otherwise the effects are
//     withdrawn, the base model kept, and the conclusion says "the residuals exceed noise and no
//     effect of the library explains them" and what to capture next. When the last round ended
//     in two effects the captures cannot tell apart, the effects adopted before it stay (the
//     ambiguity is about the rest) and the conclusion names both and what to capture next.
//  5. Every step keeps the residual RMS, maximum and chi2/dof before and after, the effect's
//     parameters with 1-sigma uncertainties, and the evidence in words.
#pragma once

#include <string>
#include <vector>

#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/calibration/diagnosis/residual_structure.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/calibration/fit/fit_summary.h"

namespace accelcal {

struct DiagnosisOptions {
  double consistency_p = 0.01;  // residuals are "noise" when the chi-square test's p >= this
  double adoption_p = 0.001;    // family-wise p-value an effect must beat to be adopted
  int max_effects = 4;          // at most this many effects are added
  bool leave_one_out = true;    // compute the leave-one-capture-out prediction of each candidate
  // Family-wise p-value below which a candidate's worst left-out prediction disqualifies it
  // (used only with leave_one_out).
  double prediction_p = 0.01;
  // The adopted set's final residuals must show no structure in pose or time at this
  // family-wise p (and pass the chi-square test at consistency_p, and predict every capture from
  // the others at prediction_p).
  double structure_p = 0.01;

  std::string Validate() const;
};

struct ResidualStats {
  double rms_mps2 = 0.0;
  double max_abs_mps2 = 0.0;
  double chi2 = 0.0;
  int dof = 0;
  double p_value = 1.0;         // chi-square test of the residuals against noise
  double Chi2PerDof() const { return dof > 0 ? chi2 / dof : 0.0; }
};

struct CandidateScore {
  std::string effect;
  std::string skipped_reason;   // non-empty: not identifiable (or the fit failed), not scored
  ResidualStats after;
  double bic = 0.0;
  double aicc = 0.0;
  double loo_rms_mps2 = -1.0;   // leave-one-capture-out prediction error; -1 when not computed
  double loo_worst_z = kNaN;    // the worst left-out prediction over its noise (scaled); NaN: none
  int loo_worst_id = 0;         // the capture it belongs to
  double lr_p_value = 1.0;      // likelihood-ratio test against the current model (uncorrected)
  // Non-empty: scored, but failed a test of the guard (prediction, plausibility), in words.
  std::string rejected_reason;
  // Passed every test of the guard and lost only the tie-break with the winner of its round, by
  // the left-out prediction, less than 6 behind it in BIC: a near-tie (calibration/near_tie.h).
  // rejected_reason says so in words.
  bool near_tie = false;
};

struct AdoptedEffect {
  std::string name;
  // Parameters and their 1-sigma from the final fit (the one with every adopted effect), not from
  // the round that adopted this one: an effect adopted later can move them.
  std::vector<std::string> parameter_names;
  std::vector<std::string> parameter_units;
  std::vector<double> parameters;
  std::vector<double> uncertainty;  // 1-sigma
  ResidualStats before;
  ResidualStats after;
  std::string evidence;             // in words
  std::string interpretation;       // the parameters in the bench's terms; may be empty
};

struct DiagnosisRound {
  ResidualStats current;                 // the model's residuals entering the round
  std::vector<CandidateScore> candidates;
  std::string outcome;                   // what the round concluded, in words
  std::string adopted;                   // the effect the round adopted; empty when none
};

struct DiagnosisReport {
  FitSummary base;                       // the seed's model alone
  FitSummary final_fit;                  // with the adopted effects (== base when none)
  // In the order adopted; each one's parameters and 1-sigma are those of final_fit.
  std::vector<AdoptedEffect> adopted;
  // The fit of each stage: the base model, then after each adopted effect (stages.back() ==
  // final_fit); empty when the base fit is not usable.
  std::vector<FitSummary> stages;
  std::vector<DiagnosisRound> rounds;
  EffectContext context;                 // reference temperature and time of the effects
  double noise_rms_mps2 = 0.0;           // RMS of the captures' own sigma_i: what noise explains
  bool consistent = false;               // the final residuals pass the chi-square test
  // The residuals exceed noise and no effect of the library explains them (none passed, or the
  // ones adopted were withdrawn: final_fit is then the base model), or the last round found two
  // effects that explain the rest alike (`ambiguous`): the effects adopted before it stay in
  // `adopted` and final_fit, and the rest is unexplained.
  bool unexplained = false;
  std::vector<std::string> withdrawn;    // effects adopted in a round, then withdrawn (step 4)
  // Two effects that explained the captures alike but imply different calibrations (step 3):
  // the captures cannot tell them apart, so neither was adopted. Empty otherwise.
  std::vector<std::string> ambiguous;
  ResidualStructure structure;           // of the final residuals (of the base when unexplained)
  std::string next_captures;             // what to capture next, in words; empty when explained
  std::string conclusion;                // one paragraph
  std::vector<std::string> adopted_names() const;
};

// Fits the base model, then runs the loop. `captures` are the used ones. When the base fit is
// not usable, the report's base says why and nothing else is done.
DiagnosisReport Diagnose(const std::vector<FitCapture>& captures, const FitOptions& fit_options,
                         const DiagnosisOptions& options);

// Several lines: before/after per adopted effect, parameters, evidence, candidates of each round.
std::string FormatDiagnosis(const DiagnosisReport& report);

}  // namespace accelcal

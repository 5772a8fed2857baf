#include "accelcal/calibration/diagnosis/diagnosis.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "accelcal/base/chi_square.h"
#include "accelcal/calibration/diagnosis/evidence.h"
#include "accelcal/calibration/diagnosis/extended_model.h"
#include "accelcal/calibration/diagnosis/leave_one_out.h"
#include "accelcal/calibration/diagnosis/rival_explanations.h"
#include "accelcal/calibration/fit/least_squares.h"

namespace accelcal {
namespace {

ResidualStats StatsOf(const FitSummary& s) {
  ResidualStats r;
  r.rms_mps2 = s.residual_rms_mps2;
  r.max_abs_mps2 = s.residual_max_abs_mps2;
  r.chi2 = s.chi2;
  r.dof = s.dof;
  r.p_value = s.dof > 0 ? ChiSquareSurvival(s.chi2, s.dof) : 1.0;
  return r;
}

bool Consistent(const ResidualStats& r, double p) { return r.dof <= 0 || r.p_value >= p; }

LeastSquaresOptions SolverOptions(const FitOptions& fit) {
  LeastSquaresOptions o = fit.solver;
  o.gravity_mps2 = fit.gravity.gravity_mps2;
  return o;
}

// Parameters of `model` starting from the previous model's solution, new effects at zero.
Eigen::VectorXd StartFrom(const Eigen::VectorXd& previous, const ExtendedResidualModel& model) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(model.NumParameters());
  p.head(previous.size()) = previous;
  return p;
}

struct Trial {
  CandidateScore score;
  FitSummary fit;
  const Effect* effect = nullptr;
  double loo_family_p = 1.0;  // of the worst left-out prediction (scaled by the fit's noise)
};

void ScoreLeftOut(const ExtendedResidualModel& model, const std::vector<FitCapture>& captures,
                  const LeastSquaresOptions& solver, Trial* t) {
  const LeaveOneOutResult loo = PredictLeftOut(model, captures, t->fit.parameters, solver);
  t->score.loo_rms_mps2 = loo.rms_mps2;
  if (loo.worst_index < 0) return;
  // Noise underestimated by the captures' own statistics inflates every z alike: judge the worst
  // against the spread the fit itself shows.
  const double scale = std::sqrt(std::max(1.0, t->fit.chi2 / t->fit.dof));
  t->score.loo_worst_z = loo.predictions[static_cast<size_t>(loo.worst_index)].z / scale;
  t->score.loo_worst_id = loo.predictions[static_cast<size_t>(loo.worst_index)].id;
  t->loo_family_p = WorstOfNormalsPValue(std::fabs(t->score.loo_worst_z), static_cast<int>(captures.size()));
}

Trial TryCandidate(const Effect* effect, const std::vector<const Effect*>& adopted,
                   const FitSummary& current, const std::vector<FitCapture>& captures,
                   const FitOptions& fit_options, const EffectContext& ctx,
                   const DiagnosisOptions& options) {
  Trial t;
  t.effect = effect;
  t.score.effect = std::string(effect->Name());
  if (std::string why = effect->WhyNotIdentifiable(captures); !why.empty()) {
    t.score.skipped_reason = why;
    return t;
  }
  std::vector<const Effect*> effects = adopted;
  effects.push_back(effect);
  const ExtendedResidualModel model(effects, ctx);
  const LeastSquaresOptions solver = SolverOptions(fit_options);
  t.fit = SolveWeightedLeastSquares(model, captures, StartFrom(current.parameters, model), solver);
  if (!t.fit.IsUsable()) {
    t.score.skipped_reason = "its fit failed: " + t.fit.message;
    return t;
  }
  if (t.fit.dof <= 0) {
    t.score.skipped_reason = "too few captures for its parameters";
    return t;
  }
  const double n = static_cast<double>(captures.size());
  const double k = model.NumParameters();
  t.score.after = StatsOf(t.fit);
  t.score.bic = t.fit.chi2 + k * std::log(n);
  t.score.aicc = t.fit.chi2 + 2.0 * k + (n - k - 1.0 > 0.0 ? 2.0 * k * (k + 1.0) / (n - k - 1.0) : INFINITY);
  const int m = effect->NumParameters();
  const double noise_scale = std::max(1.0, t.fit.chi2 / t.fit.dof);
  const double delta = std::max(0.0, current.chi2 - t.fit.chi2) / noise_scale;
  t.score.lr_p_value = ChiSquareSurvival(delta, m);
  if (options.leave_one_out) ScoreLeftOut(model, captures, solver, &t);
  return t;
}

// The ranking: BIC on the chi2 divided by one residual scale shared by the round's candidates,
// c = max(1, the smallest chi2/dof among them) (the quasi-likelihood BIC with a common
// overdispersion, Burnham & Anderson 2002, sec. 2.5), so that noise no candidate explains does
// not make small differences look decisive. Each candidate's own scale would not do: every
// candidate that explains the residuals only in part would get chi2 / scale = dof, and all of
// them would tie.
double ResidualScale(const std::vector<Trial>& trials, const std::vector<int>& ranked) {
  double smallest = INFINITY;
  for (int i : ranked) {
    const FitSummary& f = trials[static_cast<size_t>(i)].fit;
    smallest = std::min(smallest, f.chi2 / f.dof);
  }
  return std::isfinite(smallest) ? std::max(1.0, smallest) : 1.0;
}

double ScaledBic(const Trial& t, int n, double scale) {
  return t.fit.chi2 / scale + t.fit.parameters.size() * std::log(static_cast<double>(n));
}

// Two candidates that explain the captures alike imply different calibrations when exactly one
// of them corrects later readings (apply would differ), or when their nine parameters differ by
// more than twice their combined 1-sigma. Empty when they do not.
std::string NineParameterDifference(const Trial& a, const Trial& b);

std::string MaterialDifference(const Trial& a, const Trial& b) {
  if (std::string d = NineParameterDifference(a, b); !d.empty()) return d;
  if (a.effect->CorrectsReadings() != b.effect->CorrectsReadings()) {
    const Trial& corrects = a.effect->CorrectsReadings() ? a : b;
    const Trial& other = a.effect->CorrectsReadings() ? b : a;
    return fmt::format("{} would correct every later reading and {} would not",
                       corrects.score.effect, other.score.effect);
  }
  return {};
}

// Empty when the two fits' nine parameters agree within twice their combined 1-sigma.
std::string NineParameterDifference(const Trial& a, const Trial& b) {
  int worst = -1;
  double worst_sigmas = 0.0;
  for (int i = 0; i < kNumBaseParameters; ++i) {
    const double sigma = std::hypot(a.fit.uncertainty(i), b.fit.uncertainty(i));
    const double sigmas = std::fabs(a.fit.parameters(i) - b.fit.parameters(i)) / sigma;
    if (sigmas > worst_sigmas) {
      worst_sigmas = sigmas;
      worst = i;
    }
  }
  if (worst_sigmas <= 2.0) return {};
  return fmt::format("their {} differ by {:.1f} sigma", ParameterName(worst), worst_sigmas);
}

// Which of two candidates the captures favour when neither is decisively better by BIC: `best`
// is ranked first by ScaledBic, `other` is within 6 of it (short of "strong" on the Kass &
// Raftery scale). +1: best; -1: other; 0: the captures cannot tell them apart.
// - BIC within 2 ("not worth more than a bare mention"): cannot tell.
// - BIC within 2..6: the prediction of the captures each did not see decides (the smaller
//   leave-one-out RMS), as the issue asks of an adopted effect: a drift in time and a
//   temperature warm-up can fit the captures alike, but the right one predicts the first and
//   last poses from the others. Without leave-one-out, BIC decides.
int PreferredOf(const Trial& best, const Trial& other, int n, double scale) {
  const double delta = ScaledBic(other, n, scale) - ScaledBic(best, n, scale);
  if (delta < 2.0) return 0;
  if (delta >= 6.0 || other.score.loo_rms_mps2 < 0.0 || best.score.loo_rms_mps2 < 0.0) return +1;
  return other.score.loo_rms_mps2 < best.score.loo_rms_mps2 ? -1 : +1;
}

// Why `loser` is not adopted: `winner` predicts the left-out captures better (PreferredOf).
std::string PredictionVerdict(const Trial& winner, const Trial& loser) {
  return fmt::format("{} fits these captures about as well, but {} predicts each capture from the "
                     "others better (leave-one-out RMS {:.5f} against {:.5f} m/s^2)",
                     loser.score.effect, winner.score.effect, winner.score.loo_rms_mps2,
                     loser.score.loo_rms_mps2);
}

// The effect's own parameters in a fit of `model` (its index among the model's effects).
std::vector<double> EffectParameters(const FitSummary& fit, const ExtendedResidualModel& model, int e) {
  const int offset = model.Offset(e);
  const int m = model.effects()[static_cast<size_t>(e)]->NumParameters();
  return {fit.parameters.data() + offset, fit.parameters.data() + offset + m};
}

// Empty when the trial passes significance and the guard; else why not, in words.
std::string WhyNotAdopted(const Trial& t, const std::vector<const Effect*>& adopted,
                          const FitSummary& current, const std::vector<FitCapture>& captures,
                          const EffectContext& ctx, int tried, const DiagnosisOptions& options) {
  const CandidateScore& s = t.score;
  const double family_p = std::min(1.0, s.lr_p_value * tried);
  const double current_bic = current.chi2 + current.parameters.size() * std::log(double(captures.size()));
  if (s.bic >= current_bic || family_p >= options.adoption_p)
    return fmt::format("not significant (p = {:.3g} over {} candidates, needed < {:g})", family_p,
                       tried, options.adoption_p);
  if (options.leave_one_out && t.loo_family_p < options.prediction_p)
    return fmt::format("it does not predict capture {} when that one is left out: off by {:.1f} "
                       "times what noise explains (p = {:.2g} over {} captures)", s.loo_worst_id,
                       std::fabs(s.loo_worst_z), t.loo_family_p, captures.size());
  std::vector<const Effect*> effects = adopted;
  effects.push_back(t.effect);
  const ExtendedResidualModel model(effects, ctx);
  const std::vector<double> theta = EffectParameters(t.fit, model, static_cast<int>(adopted.size()));
  if (std::string why = t.effect->WhyImplausible(theta.data(), t.fit.Model(), captures); !why.empty())
    return "implausible: " + why;
  return {};
}

// The last test of step 3 (rival_explanations.h): the chosen candidate must explain the
// captures strongly better than each rival outside the library that challenges its correction
// stage: a BIC 6 or more better ("strong" on the Kass & Raftery scale). Not the 2-to-6 band that
// the left-out prediction decides between two effects of the library (PreferredOf): a rival is a
// cause the program would not correct, and the band let a drift through where the captures held
// a shift while turning (4 of 50 seeds of the physics bench, tests/physics/README.md). The rival
// named is the one that explains the captures best among those the candidate does not beat.
// Empty when the candidate stands; else why not, and `rival` names the rival.
std::string RivalVerdict(const Trial& chosen, const std::vector<const Effect*>& adopted,
                         const FitSummary& current, const std::vector<FitCapture>& captures,
                         const FitOptions& fit_options, const EffectContext& ctx,
                         const DiagnosisOptions& options, double scale, DiagnosisRound* round,
                         std::string* rival) {
  const int n = static_cast<int>(captures.size());
  DiagnosisOptions no_loo = options;
  no_loo.leave_one_out = false;  // BIC decides
  const double chosen_bic = ScaledBic(chosen, n, scale);
  std::optional<Trial> blocking;
  double blocking_bic = INFINITY;
  for (const RivalExplanation& r : RivalExplanations(captures)) {
    // A rival challenges the effects that correct at its stage: what tells them apart is the
    // variable the correction follows (time or temperature, against the table's state; the
    // input's square or cube, against its sign), not a different mechanism.
    if (r.effect->CorrectionStage() != chosen.effect->CorrectionStage()) continue;
    Trial t = TryCandidate(r.effect.get(), adopted, current, captures, fit_options, ctx, no_loo);
    if (!t.score.skipped_reason.empty()) continue;
    const double bic = ScaledBic(t, n, scale) + r.scanned_parameters * std::log(static_cast<double>(n));
    t.score.rejected_reason = fmt::format("a rival outside the library, BIC {:+.1f} from {}",
                                          bic - chosen_bic, chosen.score.effect);
    round->candidates.push_back(t.score);
    if (bic - chosen_bic < 6.0 && bic < blocking_bic) {
      blocking_bic = bic;
      blocking = std::move(t);
    }
  }
  if (!blocking) return {};
  *rival = blocking->score.effect;
  return fmt::format("{} ({}) explains the captures about as well (BIC {:+.1f}, 6 needed): these "
                     "captures cannot name {}", *rival, RivalStory(*rival), blocking_bic - chosen_bic,
                     chosen.score.effect);
}

// Runs one round: scores every candidate and returns the index of the one to adopt (the best
// by ScaledBic among those that pass WhyNotAdopted; when another that passes is within 6 of it
// and implies a different calibration, PreferredOf decides between them, and when it cannot, the
// captures cannot tell the two apart), or -1.
int RunRound(const std::vector<const Effect*>& adopted, const FitSummary& current,
             const std::vector<FitCapture>& captures, const FitOptions& fit_options,
             const EffectContext& ctx, const DiagnosisOptions& options, DiagnosisRound* round,
             std::vector<Trial>* trials, std::vector<std::string>* ambiguous) {
  for (const Effect* e : AllEffects()) {
    if (std::find(adopted.begin(), adopted.end(), e) != adopted.end()) continue;
    trials->push_back(TryCandidate(e, adopted, current, captures, fit_options, ctx, options));
  }
  const int n = static_cast<int>(captures.size());
  std::vector<int> ranked;
  for (size_t i = 0; i < trials->size(); ++i)
    if ((*trials)[i].score.skipped_reason.empty()) ranked.push_back(static_cast<int>(i));
  const double scale = ResidualScale(*trials, ranked);
  std::stable_sort(ranked.begin(), ranked.end(), [&](int a, int b) {
    return ScaledBic((*trials)[static_cast<size_t>(a)], n, scale) <
           ScaledBic((*trials)[static_cast<size_t>(b)], n, scale);
  });
  const int tried = static_cast<int>(ranked.size());
  std::vector<int> passing;
  for (int i : ranked) {
    Trial& t = (*trials)[static_cast<size_t>(i)];
    t.score.rejected_reason = WhyNotAdopted(t, adopted, current, captures, ctx, tried, options);
    if (t.score.rejected_reason.empty()) passing.push_back(i);
  }
  int chosen = passing.empty() ? -1 : passing.front();
  std::string tie;
  for (size_t k = 1; chosen >= 0 && k < passing.size(); ++k) {
    Trial& best = (*trials)[static_cast<size_t>(chosen)];
    Trial& other = (*trials)[static_cast<size_t>(passing[k])];
    if (ScaledBic(other, n, scale) - ScaledBic(best, n, scale) >= 6.0) break;
    const std::string difference = MaterialDifference(best, other);
    if (difference.empty()) continue;  // either one gives the same calibration
    const int preferred = PreferredOf(best, other, n, scale);
    if (preferred > 0) {
      other.score.rejected_reason = PredictionVerdict(best, other);
      other.score.near_tie = true;
      continue;
    }
    if (preferred < 0) {
      best.score.rejected_reason = PredictionVerdict(other, best);
      best.score.near_tie = true;
      chosen = passing[k];
      continue;
    }
    tie = fmt::format("{} and {} explain the captures alike (BIC within {:.1f}) but {}: these captures "
                      "cannot tell them apart", best.score.effect, other.score.effect,
                      ScaledBic(other, n, scale) - ScaledBic(best, n, scale), difference);
    *ambiguous = {best.score.effect, other.score.effect};
    best.score.rejected_reason = tie;
    other.score.rejected_reason = tie;
    chosen = -1;
  }
  for (const Trial& t : *trials) round->candidates.push_back(t.score);
  if (chosen >= 0 && tie.empty()) {
    Trial& c = (*trials)[static_cast<size_t>(chosen)];
    std::string rival;
    const std::string why = RivalVerdict(c, adopted, current, captures, fit_options, ctx, options,
                                         scale, round, &rival);
    if (!why.empty()) {
      c.score.rejected_reason = why;
      round->candidates[static_cast<size_t>(chosen)].rejected_reason = why;
      *ambiguous = {c.score.effect, rival};
      tie = why;
      chosen = -1;
    }
  }
  if (tried == 0) {
    round->outcome = "no candidate effect can be identified from these captures";
  } else if (!tie.empty()) {
    round->outcome = tie;
  } else if (chosen < 0) {
    const CandidateScore& best = (*trials)[static_cast<size_t>(ranked.front())].score;
    round->outcome = fmt::format("no candidate passes: the best ranked, {}, is {}", best.effect,
                                 best.rejected_reason);
  } else {
    const CandidateScore& s = (*trials)[static_cast<size_t>(chosen)].score;
    round->adopted = (*trials)[static_cast<size_t>(chosen)].score.effect;
    round->outcome = fmt::format("adopted {}: chi2/dof {:.2f} -> {:.2f}, p = {:.3g} over {} candidates",
                                 s.effect, current.Chi2PerDof(), s.after.Chi2PerDof(),
                                 std::min(1.0, s.lr_p_value * tried), tried);
  }
  return chosen;
}

AdoptedEffect Adopt(const Trial& best, const ExtendedResidualModel& model, int effect_index,
                    const FitSummary& before, const std::vector<FitCapture>& captures) {
  AdoptedEffect a;
  a.name = std::string(best.effect->Name());
  const int offset = model.Offset(effect_index);
  for (int i = 0; i < best.effect->NumParameters(); ++i) {
    a.parameter_names.push_back(best.effect->ParameterName(i));
    a.parameter_units.push_back(best.effect->ParameterUnit(i));
    a.parameters.push_back(best.fit.parameters(offset + i));
    a.uncertainty.push_back(best.fit.uncertainty(offset + i));
  }
  a.before = StatsOf(before);
  a.after = StatsOf(best.fit);
  a.evidence = Evidence(*best.effect, before, best.fit, captures);
  return a;
}

double NoiseRms(const FitSummary& s) {
  double sum = 0.0;
  for (const CaptureResidual& r : s.residuals) sum += r.sigma_mps2 * r.sigma_mps2;
  return s.residuals.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(s.residuals.size()));
}

// Each adopted effect's parameters as the final fit has them (an effect adopted in a later round
// moves the earlier ones' parameters: the round that adopted one saw a different model).
void TakeParametersFromFinalFit(const std::vector<const Effect*>& adopted, DiagnosisReport* report) {
  int offset = kNumBaseParameters;
  for (size_t e = 0; e < adopted.size(); ++e) {
    AdoptedEffect& a = report->adopted[e];
    for (int i = 0; i < adopted[e]->NumParameters(); ++i) {
      a.parameters[static_cast<size_t>(i)] = report->final_fit.parameters(offset + i);
      a.uncertainty[static_cast<size_t>(i)] = report->final_fit.uncertainty(offset + i);
    }
    a.interpretation = adopted[e]->Interpretation(a.parameters.data());
    offset += adopted[e]->NumParameters();
  }
}

std::vector<double> Standardized(const FitSummary& fit) {
  std::vector<double> z;
  for (const CaptureResidual& r : fit.residuals) z.push_back(r.residual_mps2 / r.sigma_mps2);
  return z;
}

// What a structure in the residuals asks to capture, in words.
std::string AdviceFor(const std::string& variable) {
  if (variable.find("time") != std::string::npos)
    return "repeat the first pose at the end of the session (a drift shows as one pose reading "
           "differently) and record the temperature on every capture";
  if (variable == "temperature")
    return "capture at temperatures that do not follow the session's time (warm or cool the "
           "sensor between poses)";
  if (variable.find("turntable") != std::string::npos || variable.find("centripetal") != std::string::npos)
    return "turntable runs at more radii and speeds, on a levelled table, with the radius measured "
           "to the sensor's package";
  if (variable.find("corners") != std::string::npos)
    return "more poses that load all three axes (corners), with both signs of u_x u_y u_z";
  return fmt::format("more poses at other input levels of the axis the residuals follow ({})", variable);
}

// What to capture next when the residuals are not explained: what their structure asks for,
// the captures that disagree most, and the effects these captures could not test.
std::string NextCaptures(const DiagnosisReport& report, const std::vector<FitCapture>& captures) {
  std::vector<std::string> parts;
  if (report.structure.Found(0.05))
    parts.push_back(AdviceFor(report.structure.tested[static_cast<size_t>(report.structure.strongest)].variable));
  const std::vector<double> z = Standardized(report.base);
  std::vector<size_t> order(z.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return std::fabs(z[a]) > std::fabs(z[b]); });
  std::vector<std::string> worst;
  for (size_t k = 0; k < std::min<size_t>(2, order.size()); ++k)
    worst.push_back(fmt::format("{} ({:.1f} sigma)", captures[order[k]].id, z[order[k]]));
  if (!worst.empty())
    parts.push_back(fmt::format("re-take the captures that disagree most ({}) to tell a bad capture "
                                "from an effect", fmt::join(worst, ", ")));
  for (const std::string& name : report.ambiguous) {
    if (const Effect* e = FindEffect(name))
      parts.push_back(fmt::format("to tell {} apart: {}", name, e->CapturePlan()));
    else if (std::string plan = RivalCapturePlan(name); !plan.empty())
      parts.push_back(fmt::format("to tell {} apart: {}", name, plan));
  }
  if (!report.rounds.empty()) {
    for (const CandidateScore& c : report.rounds.front().candidates) {
      const Effect* e = FindEffect(c.effect);
      if (e != nullptr && !c.skipped_reason.empty() && c.skipped_reason.rfind("its fit", 0) != 0)
        parts.push_back(fmt::format("to test {}: {}", c.effect, e->CapturePlan()));
    }
  }
  return fmt::format("{}", fmt::join(parts, "; "));
}

// Why the adopted set does not explain the residuals (step 4 of the header); empty when it does.
std::string WhyNotExplained(const std::vector<FitCapture>& captures, const FitOptions& fit_options,
                            const DiagnosisOptions& options, DiagnosisReport* report,
                            const std::vector<const Effect*>& adopted) {
  const ResidualStats last = StatsOf(report->final_fit);
  if (!Consistent(last, options.consistency_p))
    return fmt::format("their residuals still exceed noise (chi2/dof {:.2f}, p = {:.2g})",
                       last.Chi2PerDof(), last.p_value);
  if (report->structure.Found(options.structure_p)) return report->structure.Describe();
  if (!options.leave_one_out) return {};
  // The final model, judged against noise alone: each capture predicted from the others.
  const ExtendedResidualModel model(adopted, report->context);
  const LeaveOneOutResult loo =
      PredictLeftOut(model, captures, report->final_fit.parameters, SolverOptions(fit_options));
  if (loo.worst_index < 0) return {};
  const double p = WorstOfNormalsPValue(loo.worst_abs_z, static_cast<int>(captures.size()));
  if (p >= options.prediction_p) return {};
  return fmt::format("they do not predict capture {} from the others ({:.1f} times what noise "
                     "explains, p = {:.2g})", loo.predictions[static_cast<size_t>(loo.worst_index)].id,
                     loo.worst_abs_z, p);
}

// Step 4 of the header: keep the adopted effects only when they explain the residuals.
void JudgeExplained(const std::vector<FitCapture>& captures, const FitOptions& fit_options,
                    const DiagnosisOptions& options, const std::vector<const Effect*>& adopted,
                    DiagnosisReport* report) {
  if (report->consistent && report->adopted.empty()) return;
  std::string why_withdrawn;
  if (!report->adopted.empty()) {
    report->structure = FindResidualStructure(captures, Standardized(report->final_fit));
    why_withdrawn = WhyNotExplained(captures, fit_options, options, report, adopted);
    if (why_withdrawn.empty()) return;
    if (report->ambiguous.size() == 2) {
      // The last round found two effects that explain the rest alike: the effects adopted before
      // it were adopted on their own evidence and stay (withdrawing them too would leave a worse
      // model for an ambiguity that is not theirs); the rest stays unexplained.
      report->unexplained = true;
      report->next_captures = NextCaptures(*report, captures);
      report->conclusion = fmt::format(
          "{} added; the rest of the residuals (chi2/dof {:.2f}) is explained alike by {} and by "
          "{}, which imply different calibrations: these captures cannot tell them apart, so "
          "neither is added; next: {}", fmt::join(report->adopted_names(), " + "),
          report->final_fit.Chi2PerDof(), report->ambiguous[0], report->ambiguous[1],
          report->next_captures);
      return;
    }
    for (const AdoptedEffect& a : report->adopted) report->withdrawn.push_back(a.name);
    report->adopted.clear();
    report->final_fit = report->base;
    report->stages.resize(1);
    report->consistent = false;
  }
  report->unexplained = true;
  report->structure = FindResidualStructure(captures, Standardized(report->base));
  report->next_captures = NextCaptures(*report, captures);
  std::string text = "the residuals exceed noise and no effect of the library explains them";
  if (!report->withdrawn.empty())
    text += fmt::format(" ({} fitted better but {}: withdrawn, the base model kept)",
                        fmt::join(report->withdrawn, " + "), why_withdrawn);
  else if (report->ambiguous.size() == 2)
    text += fmt::format(" alone ({} and {} explain them alike and imply different calibrations)",
                        report->ambiguous[0], report->ambiguous[1]);
  else if (report->structure.Found(options.structure_p))
    text += " (" + report->structure.Describe() + ")";
  report->conclusion = text + "; next: " + report->next_captures;
}

}  // namespace

std::string DiagnosisOptions::Validate() const {
  if (!(consistency_p > 0.0 && consistency_p < 1.0)) return "consistency_p must be in (0, 1)";
  if (!(adoption_p > 0.0 && adoption_p < 1.0)) return "adoption_p must be in (0, 1)";
  if (!(prediction_p > 0.0 && prediction_p < 1.0)) return "prediction_p must be in (0, 1)";
  if (!(structure_p > 0.0 && structure_p < 1.0)) return "structure_p must be in (0, 1)";
  if (max_effects < 0) return "max_effects must be >= 0";
  return {};
}

std::vector<std::string> DiagnosisReport::adopted_names() const {
  std::vector<std::string> names;
  for (const AdoptedEffect& a : adopted) names.push_back(a.name);
  return names;
}

DiagnosisReport Diagnose(const std::vector<FitCapture>& captures, const FitOptions& fit_options,
                         const DiagnosisOptions& options) {
  DiagnosisReport report;
  report.base = FitCalibration(captures, fit_options);
  report.final_fit = report.base;
  if (!report.base.IsUsable()) {
    report.conclusion = "no diagnosis: the base fit failed (" + report.base.message + ")";
    return report;
  }
  report.noise_rms_mps2 = NoiseRms(report.base);
  report.stages.push_back(report.base);
  const EffectContext ctx = MakeEffectContext(captures, fit_options.gravity.gravity_mps2);
  // The extended fits hold what the base fit held: a reduced model stays reduced.
  FitOptions held_options = fit_options;
  for (const HeldParameter& h : report.base.held) held_options.solver.held.push_back(h.index);
  report.context = ctx;
  std::vector<const Effect*> adopted;
  while (true) {
    DiagnosisRound round;
    round.current = StatsOf(report.final_fit);
    if (Consistent(round.current, options.consistency_p)) {
      round.outcome = fmt::format("the residuals are what noise explains (chi2/dof {:.2f}, p = {:.3g})",
                                  round.current.Chi2PerDof(), round.current.p_value);
      report.rounds.push_back(round);
      report.consistent = true;
      break;
    }
    if (static_cast<int>(adopted.size()) >= options.max_effects) {
      round.outcome = fmt::format("stopped after {} effects (the limit)", adopted.size());
      report.rounds.push_back(round);
      break;
    }
    std::vector<Trial> trials;
    const int best = RunRound(adopted, report.final_fit, captures, held_options, ctx, options, &round,
                              &trials, &report.ambiguous);
    report.rounds.push_back(round);
    if (best < 0) break;
    adopted.push_back(trials[static_cast<size_t>(best)].effect);
    const ExtendedResidualModel model(adopted, ctx);
    report.adopted.push_back(Adopt(trials[static_cast<size_t>(best)], model,
                                   static_cast<int>(adopted.size()) - 1, report.final_fit, captures));
    report.adopted.back().evidence += RunnersUp(report.rounds.back().candidates, best);
    report.final_fit = trials[static_cast<size_t>(best)].fit;
    report.stages.push_back(report.final_fit);
  }
  TakeParametersFromFinalFit(adopted, &report);
  const ResidualStats last = StatsOf(report.final_fit);
  if (report.adopted.empty())
    report.conclusion = report.consistent ? "the nine-parameter model explains the captures: no effect added"
                                          : "the residuals exceed the noise (no effect looked for)";
  else
    report.conclusion = fmt::format("{} effect(s) added; residual RMS {:.5f} -> {:.5f} m/s^2 (noise explains "
                        "{:.5f}); {}",
                        report.adopted.size(), report.base.residual_rms_mps2, last.rms_mps2,
                        report.noise_rms_mps2,
                        "the residuals are now what noise explains");
  if (options.max_effects > 0) JudgeExplained(captures, held_options, options, adopted, &report);
  return report;
}

}  // namespace accelcal

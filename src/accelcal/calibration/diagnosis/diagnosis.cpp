#include "accelcal/calibration/diagnosis/diagnosis.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/base/chi_square.h"
#include "accelcal/calibration/diagnosis/extended_model.h"
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

bool Consistent(const ResidualStats& r, const DiagnosisOptions& o) {
  return r.dof <= 0 || r.p_value >= o.consistency_p;
}

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

// Leave-one-capture-out: refit without each capture (warm-started) and predict it.
double LeaveOneOutRms(const ExtendedResidualModel& model, const std::vector<FitCapture>& captures,
                      const Eigen::VectorXd& p_full, const LeastSquaresOptions& solver) {
  double sum_sq = 0.0;
  std::vector<FitCapture> rest;
  for (size_t i = 0; i < captures.size(); ++i) {
    rest.clear();
    for (size_t j = 0; j < captures.size(); ++j)
      if (j != i) rest.push_back(captures[j]);
    const FitSummary s = SolveWeightedLeastSquares(model, rest, p_full, solver);
    const Eigen::VectorXd& p = s.IsUsable() ? s.parameters : p_full;
    const double r = model.Residual(p, captures[i], solver.gravity_mps2, nullptr, nullptr);
    sum_sq += r * r;
  }
  return std::sqrt(sum_sq / static_cast<double>(captures.size()));
}

struct Trial {
  CandidateScore score;
  FitSummary fit;
  const Effect* effect = nullptr;
};

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
  if (options.leave_one_out) t.score.loo_rms_mps2 = LeaveOneOutRms(model, captures, t.fit.parameters, solver);
  return t;
}

double Correlation(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) { mx += x[i] / n; my += y[i] / n; }
  double sxy = 0, sxx = 0, syy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

// How the residuals before the effect relate to its physical variable, by capture kind.
std::string RegressorEvidence(const Effect& effect, const FitSummary& before,
                              const std::vector<FitCapture>& captures) {
  if (effect.RegressorName().empty()) return {};
  std::vector<double> x, y;
  int static_without = 0;
  double static_rms = 0.0;
  for (size_t i = 0; i < captures.size(); ++i) {
    const double v = effect.Regressor(captures[i]);
    const double r = before.residuals[i].residual_mps2;
    if (std::isfinite(v)) {
      x.push_back(v);
      y.push_back(r);
    } else if (captures[i].kind == CaptureKind::kStatic) {
      ++static_without;
      static_rms += r * r;
    }
  }
  if (x.size() < 3 || *std::max_element(x.begin(), x.end()) == *std::min_element(x.begin(), x.end()))
    return {};
  const double rho = Correlation(x, y);
  std::string out = fmt::format("the residuals before it {} with {} (correlation {:+.2f} over {} captures)",
                                rho >= 0 ? "grow" : "fall", effect.RegressorName(), rho, x.size());
  if (static_without > 0)
    out += fmt::format("; static captures, which have no {}, show an RMS of {:.4f} m/s^2",
                       effect.RegressorName(), std::sqrt(static_rms / static_without));
  return out;
}

// Where the adopted effect changed the residuals: by capture kind, and how well that change
// matches the residuals it explains.
std::string Evidence(const Effect& effect, const FitSummary& before, const FitSummary& after,
                     const std::vector<FitCapture>& captures) {
  double max_static = 0.0, max_turntable = 0.0, sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (size_t i = 0; i < captures.size(); ++i) {
    const double r = before.residuals[i].residual_mps2;
    const double explained = r - after.residuals[i].residual_mps2;
    double& max = captures[i].kind == CaptureKind::kStatic ? max_static : max_turntable;
    max = std::max(max, std::fabs(explained));
    sxy += r * explained;
    sxx += explained * explained;
    syy += r * r;
  }
  const double share = syy > 0.0 ? 1.0 - (syy - 2 * sxy + sxx) / syy : 0.0;
  std::string out = std::string(effect.Story());
  if (std::string by_variable = RegressorEvidence(effect, before, captures); !by_variable.empty())
    out += ": " + by_variable;
  out += fmt::format("; adding it changes turntable residuals by up to {:.4f} m/s^2 and static ones "
                     "by up to {:.4f}, and accounts for {:.0f} % of the residual sum of squares",
                     max_turntable, max_static, 100.0 * std::clamp(share, 0.0, 1.0));
  return out;
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

// The ranking: the leave-one-capture-out prediction error when it was computed (it judges each
// candidate on captures it did not see, which separates near-collinear effects such as a
// temperature warm-up and a drift in time better than the fit's own chi2), else BIC.
bool RanksBefore(const CandidateScore& a, const CandidateScore& b) {
  if (a.loo_rms_mps2 >= 0.0 && b.loo_rms_mps2 >= 0.0) return a.loo_rms_mps2 < b.loo_rms_mps2;
  return a.bic < b.bic;
}

// Other candidates worth naming beside the adopted one: those within 6 of its BIC (closer than
// "strong" evidence on the Kass & Raftery scale), and those that fit these captures more closely
// by BIC but predicted the left-out captures worse.
std::string RunnersUp(const std::vector<Trial>& trials, int best) {
  const CandidateScore& b = trials[best].score;
  std::string out;
  for (size_t i = 0; i < trials.size(); ++i) {
    const CandidateScore& c = trials[i].score;
    if (static_cast<int>(i) == best || !c.skipped_reason.empty()) continue;
    const double diff = c.bic - b.bic;
    if (std::fabs(diff) < 6.0)
      out += fmt::format("; {} explains the captures almost as well (BIC {:+.1f})", c.effect, diff);
    else if (diff < 0.0 && c.loo_rms_mps2 >= 0.0)
      out += fmt::format("; {} fits these captures more closely (BIC {:+.1f}) but predicts left-out "
                         "captures worse ({:.5f} against {:.5f} m/s^2)",
                         c.effect, diff, c.loo_rms_mps2, b.loo_rms_mps2);
  }
  return out;
}

// Runs one round: scores every candidate and returns the index of the one to adopt, or -1.
int RunRound(const std::vector<const Effect*>& adopted, const FitSummary& current,
             const std::vector<FitCapture>& captures, const FitOptions& fit_options,
             const EffectContext& ctx, const DiagnosisOptions& options, DiagnosisRound* round,
             std::vector<Trial>* trials) {
  for (const Effect* e : AllEffects()) {
    if (std::find(adopted.begin(), adopted.end(), e) != adopted.end()) continue;
    trials->push_back(TryCandidate(e, adopted, current, captures, fit_options, ctx, options));
    round->candidates.push_back(trials->back().score);
  }
  int best = -1, tried = 0;
  for (size_t i = 0; i < trials->size(); ++i) {
    if (!(*trials)[i].score.skipped_reason.empty()) continue;
    ++tried;
    if (best < 0 || RanksBefore((*trials)[i].score, (*trials)[best].score)) best = static_cast<int>(i);
  }
  if (best < 0) {
    round->outcome = "no candidate effect can be identified from these captures";
    return -1;
  }
  const CandidateScore& s = (*trials)[best].score;
  const double family_p = std::min(1.0, s.lr_p_value * tried);
  if (s.bic >= current.chi2 + current.parameters.size() * std::log(double(captures.size())) ||
      family_p >= options.adoption_p) {
    round->outcome = fmt::format("the best candidate, {}, is not significant (p = {:.3g} over {} "
                                 "candidates, needed < {:g})", s.effect, family_p, tried,
                                 options.adoption_p);
    return -1;
  }
  round->outcome = fmt::format("adopted {}: chi2/dof {:.2f} -> {:.2f}, p = {:.3g} over {} candidates",
                               s.effect, current.Chi2PerDof(), s.after.Chi2PerDof(), family_p, tried);
  return best;
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
    offset += adopted[e]->NumParameters();
  }
}

}  // namespace

std::string DiagnosisOptions::Validate() const {
  if (!(consistency_p > 0.0 && consistency_p < 1.0)) return "consistency_p must be in (0, 1)";
  if (!(adoption_p > 0.0 && adoption_p < 1.0)) return "adoption_p must be in (0, 1)";
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
    if (Consistent(round.current, options)) {
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
    const int best = RunRound(adopted, report.final_fit, captures, held_options, ctx, options, &round, &trials);
    report.rounds.push_back(round);
    if (best < 0) break;
    adopted.push_back(trials[best].effect);
    const ExtendedResidualModel model(adopted, ctx);
    report.adopted.push_back(Adopt(trials[best], model, static_cast<int>(adopted.size()) - 1,
                                   report.final_fit, captures));
    report.adopted.back().evidence += RunnersUp(trials, best);
    report.final_fit = trials[best].fit;
    report.stages.push_back(report.final_fit);
  }
  TakeParametersFromFinalFit(adopted, &report);
  const ResidualStats last = StatsOf(report.final_fit);
  report.conclusion =
      report.adopted.empty()
          ? (report.consistent ? "the seed's model explains the captures: no effect added"
                               : "the residuals exceed the noise but no effect of the library "
                                 "explains them significantly")
          : fmt::format("{} effect(s) added; residual RMS {:.5f} -> {:.5f} m/s^2 (noise explains "
                        "{:.5f}); {}",
                        report.adopted.size(), report.base.residual_rms_mps2, last.rms_mps2,
                        report.noise_rms_mps2,
                        report.consistent ? "the residuals are now what noise explains"
                                          : "the residuals still exceed the noise");
  return report;
}

std::string FormatDiagnosis(const DiagnosisReport& report) {
  std::string out = "diagnosis: " + report.conclusion + "\n";
  for (const AdoptedEffect& a : report.adopted) {
    out += fmt::format("  + {}: RMS {:.5f} -> {:.5f} m/s^2, max {:.5f} -> {:.5f}, chi2/dof {:.2f} -> {:.2f}\n",
                       a.name, a.before.rms_mps2, a.after.rms_mps2, a.before.max_abs_mps2,
                       a.after.max_abs_mps2, a.before.Chi2PerDof(), a.after.Chi2PerDof());
    for (size_t i = 0; i < a.parameters.size(); ++i)
      out += fmt::format("      {:<10} {:>14.6g} +- {:<11.3g} {}\n", a.parameter_names[i],
                         a.parameters[i], a.uncertainty[i], a.parameter_units[i]);
    out += "      evidence: " + a.evidence + "\n";
  }
  for (size_t r = 0; r < report.rounds.size(); ++r) {
    const DiagnosisRound& round = report.rounds[r];
    out += fmt::format("  round {}: {}\n", r + 1, round.outcome);
    for (const CandidateScore& c : round.candidates) {
      if (!c.skipped_reason.empty()) {
        out += fmt::format("      {:<24} skipped: {}\n", c.effect, c.skipped_reason);
        continue;
      }
      out += fmt::format("      {:<24} chi2/dof {:>8.2f}  BIC {:>10.1f}  AICc {:>10.1f}{}  p {:.2g}\n",
                         c.effect, c.after.Chi2PerDof(), c.bic, c.aicc,
                         c.loo_rms_mps2 >= 0 ? fmt::format("  LOO {:.5f}", c.loo_rms_mps2) : "",
                         c.lr_p_value);
    }
  }
  return out;
}

}  // namespace accelcal

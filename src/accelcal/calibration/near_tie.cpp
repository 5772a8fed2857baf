#include "accelcal/calibration/near_tie.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/calibration/diagnosis/effect.h"
#include "accelcal/calibration/diagnosis/extended_model.h"
#include "accelcal/calibration/fit/least_squares.h"

namespace accelcal {
namespace {

// Below this BIC gap the evidence for the winner is not "strong" (Kass & Raftery 1995).
constexpr double kStrongBic = 6.0;

// Passed every test of the guard, or lost only the diagnosis's tie-break by the left-out
// prediction (CandidateScore::near_tie).
bool Passed(const CandidateScore& c) {
  return c.skipped_reason.empty() && (c.rejected_reason.empty() || c.near_tie);
}

// The hypothetical captures a bench can add: the six faces, and each signed axis radial at the
// session's largest radius and speed (up: the next axis).
std::vector<FitCapture> ProbeCaptures(const std::vector<FitCapture>& captures, const EffectContext& ctx) {
  double radius_m = kNaN, rpm = kNaN;
  for (const FitCapture& c : captures)
    if (c.kind == CaptureKind::kTurntable && !(c.radius_m * c.rpm * c.rpm <= radius_m * rpm * rpm)) {
      radius_m = c.radius_m;
      rpm = c.rpm;
    }
  std::vector<FitCapture> out;
  const SensorAxis axes[] = {SensorAxis::kPlusX, SensorAxis::kMinusX, SensorAxis::kPlusY,
                             SensorAxis::kMinusY, SensorAxis::kPlusZ, SensorAxis::kMinusZ};
  const SensorAxis ups[] = {SensorAxis::kPlusZ, SensorAxis::kPlusZ, SensorAxis::kPlusX,
                            SensorAxis::kPlusX, SensorAxis::kPlusY, SensorAxis::kPlusY};
  for (int k = 0; k < 6; ++k) {
    FitCapture c;
    c.kind = CaptureKind::kStatic;
    c.mean_t_s = ctx.t_ref_s;
    c.mean_temp_c = ctx.temp_ref_c;
    c.up_axis = axes[k];  // read back below for the words
    out.push_back(c);
  }
  if (std::isfinite(radius_m) && std::isfinite(rpm))
    for (int k = 0; k < 6; ++k) {
      FitCapture c;
      c.kind = CaptureKind::kTurntable;
      c.radius_m = radius_m;
      c.rpm = rpm;
      c.up_axis = ups[k];
      c.id = k;  // the radial axis, axes[k]
      c.mean_t_s = ctx.t_ref_s;
      c.mean_temp_c = ctx.temp_ref_c;
      out.push_back(c);
    }
  return out;
}

// The specific force of a probe in the sensor frame, m/s^2.
Eigen::Vector3d ProbeForce(const FitCapture& c, double g) {
  static const SensorAxis kAxes[] = {SensorAxis::kPlusX, SensorAxis::kMinusX, SensorAxis::kPlusY,
                                     SensorAxis::kMinusY, SensorAxis::kPlusZ, SensorAxis::kMinusZ};
  if (c.kind == CaptureKind::kStatic) return g * SensorAxisVector(*c.up_axis);
  const double w = RpmToRadPerS(c.rpm);
  return g * SensorAxisVector(*c.up_axis) - w * w * c.radius_m * SensorAxisVector(kAxes[c.id]);
}

std::string ProbeWords(const FitCapture& c) {
  static const SensorAxis kAxes[] = {SensorAxis::kPlusX, SensorAxis::kMinusX, SensorAxis::kPlusY,
                                     SensorAxis::kMinusY, SensorAxis::kPlusZ, SensorAxis::kMinusZ};
  if (c.kind == CaptureKind::kStatic) return fmt::format("a static capture {} up", SensorAxisToString(*c.up_axis));
  return fmt::format("a turntable run with {} radial at {:g} m and {:g} rpm", SensorAxisToString(kAxes[c.id]),
                     c.radius_m, c.rpm);
}

// The probe the two fitted models read most differently, and by how many sigmas.
void FindSeparating(const ResidualModel& a, const Eigen::VectorXd& pa, const ResidualModel& b,
                    const Eigen::VectorXd& pb, const std::vector<FitCapture>& captures,
                    const EffectContext& ctx, NearTie* tie) {
  std::vector<double> sigmas;
  for (const FitCapture& c : captures) sigmas.push_back(std::sqrt(c.mean_cov_counts2.trace() / 3.0));
  std::nth_element(sigmas.begin(), sigmas.begin() + sigmas.size() / 2, sigmas.end());
  const double sigma_counts = sigmas[sigmas.size() / 2];
  const SensorModel base = SensorModel::FromVector(pa.head(kNumBaseParameters));
  double best = -1.0;
  for (FitCapture probe : ProbeCaptures(captures, ctx)) {
    probe.mean_counts = base.Raw(ProbeForce(probe, ctx.gravity_mps2));
    probe.mean_cov_counts2 = Eigen::Matrix3d::Identity() * sigma_counts * sigma_counts;
    Eigen::Vector3d grad;
    const double ra = a.Residual(pa, probe, ctx.gravity_mps2, nullptr, &grad);
    const double rb = b.Residual(pb, probe, ctx.gravity_mps2, nullptr, nullptr);
    const double sigma_mps2 = grad.norm() * sigma_counts;
    const double z = std::fabs(ra - rb) / sigma_mps2;
    if (std::isfinite(z) && z > best) {
      best = z;
      tie->separating = ProbeWords(probe);
    }
  }
  tie->separation_sigmas = best;
}

}  // namespace

std::vector<NearTie> FindNearTies(const DiagnosisReport& diagnosis,
                                  const std::vector<FitCapture>& captures, const FitOptions& options) {
  std::vector<NearTie> ties;
  const FitSummary& final_fit = diagnosis.final_fit;
  if (diagnosis.adopted.empty() || !final_fit.IsUsable() || !final_fit.held.empty()) return ties;
  std::vector<const Effect*> adopted;
  for (const AdoptedEffect& a : diagnosis.adopted)
    if (const Effect* e = FindEffect(a.name)) adopted.push_back(e);
  if (adopted.size() != diagnosis.adopted.size()) return ties;
  const ExtendedResidualModel adopted_model(adopted, diagnosis.context);
  LeastSquaresOptions solver = options.solver;
  solver.gravity_mps2 = options.gravity.gravity_mps2;

  for (const DiagnosisRound& round : diagnosis.rounds) {
    const std::string& winner = round.adopted;
    if (winner.empty()) continue;
    const auto won = std::find_if(round.candidates.begin(), round.candidates.end(),
                                  [&](const CandidateScore& c) { return c.effect == winner; });
    if (won == round.candidates.end()) continue;
    // The round's shared residual scale (diagnosis.cpp's ranking): max(1, smallest chi2/dof).
    double smallest = INFINITY;
    for (const CandidateScore& c : round.candidates)
      if (Passed(c) && c.after.dof > 0) smallest = std::min(smallest, c.after.Chi2PerDof());
    const double scale = std::isfinite(smallest) ? std::max(1.0, smallest) : 1.0;
    const double winner_bic = won->after.chi2 / scale + (won->bic - won->after.chi2);
    for (const CandidateScore& c : round.candidates) {
      if (c.effect == winner || !Passed(c)) continue;
      const double gap = c.after.chi2 / scale + (c.bic - c.after.chi2) - winner_bic;
      if (!(gap < kStrongBic)) continue;
      const Effect* rival = FindEffect(c.effect);
      if (!rival) continue;
      std::vector<const Effect*> effects = adopted;
      std::replace(effects.begin(), effects.end(), FindEffect(winner), rival);
      const ExtendedResidualModel rival_model(effects, diagnosis.context);
      Eigen::VectorXd start = Eigen::VectorXd::Zero(rival_model.NumParameters());
      start.head(kNumBaseParameters) = final_fit.parameters.head(kNumBaseParameters);
      const FitSummary rival_fit = SolveWeightedLeastSquares(rival_model, captures, start, solver);
      if (!rival_fit.IsUsable()) continue;
      NearTie tie;
      tie.adopted = winner;
      tie.rival = c.effect;
      tie.bic_gap = std::max(0.0, gap);
      tie.dof_left = won->after.dof;
      tie.parameter_shift = rival_fit.parameters.head(kNumBaseParameters) -
                            final_fit.parameters.head(kNumBaseParameters);
      tie.shift_sigmas = tie.parameter_shift.cwiseAbs().cwiseQuotient(
          final_fit.uncertainty.head(kNumBaseParameters));
      FindSeparating(adopted_model, final_fit.parameters, rival_model, rival_fit.parameters, captures,
                     diagnosis.context, &tie);
      ties.push_back(std::move(tie));
    }
  }
  return ties;
}

void WidenForNearTies(const std::vector<NearTie>& ties, FitSummary* fit) {
  for (const NearTie& t : ties) {
    const Eigen::VectorXd& d = t.parameter_shift;
    fit->covariance.topLeftCorner(kNumBaseParameters, kNumBaseParameters) += 0.25 * d * d.transpose();
    for (int i = 0; i < kNumBaseParameters; ++i)
      if (std::isfinite(fit->uncertainty(i)))
        fit->uncertainty(i) = std::sqrt(fit->uncertainty(i) * fit->uncertainty(i) + 0.25 * d(i) * d(i));
  }
}

std::string NearTieWords(const NearTie& t) {
  int worst = 0;
  for (int i = 1; i < kNumBaseParameters; ++i)
    if (t.shift_sigmas(i) > t.shift_sigmas(worst)) worst = i;
  std::string separate = t.separation_sigmas >= 1.0
                             ? fmt::format("{} tells them apart (they read it {:.1f} sigma apart)",
                                           t.separating, t.separation_sigmas)
                             : std::string("no single added capture of the standard kinds tells them apart well");
  return fmt::format("limited by a choice these captures cannot make: {} and {} explain them about "
                     "equally (BIC {:.1f} apart, under 6, with {} degrees of freedom left); {} was "
                     "adopted, {} would move {} by {:.1f} sigma, and the uncertainties include that "
                     "choice; {}",
                     t.adopted, t.rival, t.bic_gap, t.dof_left, t.adopted, t.rival,
                     ParameterName(worst), t.shift_sigmas(worst), separate);
}

}  // namespace accelcal

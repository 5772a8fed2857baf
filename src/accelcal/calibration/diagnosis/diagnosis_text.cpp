// FormatDiagnosis (diagnosis.h): the diagnosis in lines of text.
#include <cmath>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "accelcal/calibration/diagnosis/diagnosis.h"

namespace accelcal {
namespace {

std::string CandidateLine(const CandidateScore& c) {
  if (!c.skipped_reason.empty()) return fmt::format("      {:<24} skipped: {}\n", c.effect, c.skipped_reason);
  std::string out = fmt::format("      {:<24} chi2/dof {:>8.2f}  BIC {:>10.1f}  AICc {:>10.1f}{}  p {:.2g}\n",
                                c.effect, c.after.Chi2PerDof(), c.bic, c.aicc,
                                c.loo_rms_mps2 >= 0 ? fmt::format("  LOO {:.5f}", c.loo_rms_mps2) : "",
                                c.lr_p_value);
  if (!c.rejected_reason.empty()) out += fmt::format("      {:<24}   not adopted: {}\n", "", c.rejected_reason);
  return out;
}

}  // namespace

std::string FormatDiagnosis(const DiagnosisReport& report) {
  std::string out = "diagnosis: " + report.conclusion + "\n";
  for (const AdoptedEffect& a : report.adopted) {
    out += fmt::format("  + {}: RMS {:.5f} -> {:.5f} m/s^2, max {:.5f} -> {:.5f}, chi2/dof {:.2f} -> {:.2f}\n",
                       a.name, a.before.rms_mps2, a.after.rms_mps2, a.before.max_abs_mps2,
                       a.after.max_abs_mps2, a.before.Chi2PerDof(), a.after.Chi2PerDof());
    for (size_t i = 0; i < a.parameters.size(); ++i)
      out += fmt::format("      {:<10} {:>14.6g} +- {:<11.3g} {}\n", a.parameter_names[i],
                         a.parameters[i], a.uncertainty[i], UnitAfterValue(a.parameter_units[i]));
    if (!a.interpretation.empty()) out += "      that is " + a.interpretation + "\n";
    out += "      evidence: " + a.evidence + "\n";
  }
  if (!report.withdrawn.empty())
    out += fmt::format("  withdrawn: {} (see the conclusion)\n", fmt::join(report.withdrawn, ", "));
  for (size_t r = 0; r < report.rounds.size(); ++r) {
    const DiagnosisRound& round = report.rounds[r];
    out += fmt::format("  round {}: {}\n", r + 1, round.outcome);
    for (const CandidateScore& c : round.candidates) out += CandidateLine(c);
  }
  return out;
}

}  // namespace accelcal

#include "accelcal/app/wizard/settling_wait.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "accelcal/app/wizard/wizard_session.h"
#include "accelcal/calibration/settling.h"

namespace accelcal {
namespace {

// At most: 10 s captures tell a settling time of 10 s from one of a minute poorly (settling.h),
// and the estimate leans long; two minutes per pose at most (a shorter cap left clumsy_settling
// with scales of 3900 ppm 1-sigma: FAIL).
constexpr double kLongestWaitS = 120.0;
constexpr double kMostSettlingTimes = 4.0;
// What may be left of the change of pose when the capture begins: this many standard errors of
// the capture's mean (the fit's settled readings take care of the rest).
constexpr double kLeftInStandardErrors = 2.0;

}  // namespace

SettlingWait PlanSettlingWait(std::vector<Capture> captured, const Eigen::Vector3d& expected_counts) {
  if (captured.empty()) return {};
  const CaptureStats last = captured.back().stats();
  const SettlingFinding f = HandleSettling(captured);
  if (!f.detected || !(f.tau_s > 0.0) || last.n < 2) return {};
  const Eigen::Vector3d change = last.mean_counts - expected_counts;
  const Eigen::Vector3d standard_error = last.StdCounts() / std::sqrt(static_cast<double>(last.n));
  double need = 0.0;  // the largest axis' lag at the usual start over what may be left
  for (int j = 0; j < 3; ++j)
    if (standard_error(j) > 0.0)
      need = std::max(need, std::abs(f.lag_share(j) * change(j)) / (kLeftInStandardErrors * standard_error(j)));
  if (!(need > 1.0)) return {};
  const double wait_s = std::ceil(std::min({f.tau_s * std::log(need), kMostSettlingTimes * f.tau_s, kLongestWaitS}));
  return {wait_s, fmt::format("still settling after you set it down: the earlier poses were still moving "
                              "{:.1f} counts as their capture began (settling time about {:.0f} s)",
                              f.largest_offset_counts, f.tau_s)};
}

void AddSettlingWait(const WizardSession& session, CaptureRequest& request) {
  std::vector<Capture> captured;
  for (const JournalCapture& c : CurrentCaptures(session.model.captures()))
    if (session.model.LeftOutReason(c).empty() && c.capture.id != session.sequence.ReplacedCaptureId())
      captured.push_back(c.capture);
  std::stable_sort(captured.begin(), captured.end(), [](const Capture& a, const Capture& b) {
    return a.stats().t_first_s < b.stats().t_first_s;
  });
  const Eigen::Vector3d expected =
      session.procedure.nominal.Raw(session.gravity.gravity_mps2 * request.expected.up.normalized());
  const SettlingWait wait = PlanSettlingWait(std::move(captured), expected);
  if (!(wait.wait_s > 0.0)) return;
  request.settle_wait_s = wait.wait_s;
  request.settle_wait_reason = wait.reason;
  request.timeout_s += wait.wait_s;
}

}  // namespace accelcal

#include "cli/vehicle_writeback_cli.h"

#include <iostream>

#include <fmt/core.h>

#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/app/device/vehicle_writeback.h"
#include "accelcal/base/error.h"

namespace accelcal::cli {

void WriteBackToVehicle(const Calibration& cal, const std::string& target,
                        const std::optional<DriverScaleOptions>& driver, bool apply) {
  const MavlinkSourceSpec spec = ParseMavlinkSpec(target);
  std::optional<DriverScaleOptions> scaling = driver ? driver : DriverScaleOfUnit(cal.reading_unit);
  if (!scaling)
    throw Error("this calibration is in counts, so the driver's scaling is needed to turn it into the "
                "autopilot's offsets and scales: give --nominal-scale-counts-per-mps2 (and "
                "--nominal-bias-counts) or --procedure FILE (for a MAVLink session, "
                "procedures/autopilot_imu.toml: 1000 counts per m/s^2, zero 0)");
  mavlink::Connection link(spec.link, {.system = spec.system, .component = spec.component});
  mavlink::AwaitVehicle(link, {});
  const FlightStack stack = StackOf(link.vehicle().autopilot);
  const WritebackPlan plan = PlanWriteback(cal, stack, spec.imu, *scaling);
  std::cout << fmt::format("{} on {}, IMU {}: {} accelerometer parameters\n", link.vehicle().Describe(),
                           link.LinkName(), spec.imu, StackName(stack));
  for (const std::string& line : DescribeWrites(plan.writes)) std::cout << line << "\n";
  for (const std::string& s : plan.cannot_hold) std::cout << "cannot hold: " << s << "\n";
  for (const std::string& s : plan.notes) std::cout << "note: " << s << "\n";
  if (!apply) {
    std::cout << "dry run: nothing was sent (--apply sends these PARAM_SETs, waits for each echo and "
                 "reads every value back)\n";
    return;
  }
  const WritebackOutcome outcome = ApplyWrites(link, stack, plan.writes);
  for (const std::string& line : outcome.Lines()) std::cout << line << "\n";
  std::cout.flush();
  if (!outcome.ok())
    throw Error(fmt::format("the write-back to {} stopped: {}", link.LinkName(),
                            outcome.failed.empty() ? outcome.reread_mismatches.front() : outcome.failed));
}

}  // namespace accelcal::cli

#include "accelcal/app/device/vehicle_session.h"

#include <fmt/format.h>

namespace accelcal {
namespace {

// One IMU instance (the source's lane): its parameters said, the choice applied; a refusal of
// the undo returned (empty: none).
std::string PrepareLane(MavlinkSource& source, std::size_t lane, VehicleCalibrationChoice choice,
                        const mavlink::ParamExchange& exchange, std::vector<std::string>* lines) {
  const int imu = source.imu(lane);
  const VehicleAccelParams params = ReadVehicleAccelParams(source.connection(), imu, exchange);
  const std::vector<std::string> said = DescribeVehicleAccelParams(params);
  lines->insert(lines->end(), said.begin(), said.end());
  if (choice == VehicleCalibrationChoice::kAsIs) {
    source.SetUndo(lane, std::nullopt);
    lines->push_back("left in the readings (as asked): the calibration will describe the sensor after "
                     "the vehicle's own correction, not the sensor itself");
    return {};
  }
  std::string why;
  std::optional<mavlink::AccelUndo> undo = UndoOf(params, &why);
  if (!undo) {
    MavlinkSourceSpec one = source.spec();
    one.imu = imu;
    return fmt::format(
        "{}{}: the vehicle's own calibration cannot be taken out of its readings: {}. Reset it on the "
        "vehicle (accelcal device-info --source {} --reset --apply writes offsets 0 and scales 1), or "
        "keep it knowingly (--vehicle-calibration as-is)",
        source.connection().LinkName(), source.imu_count() > 1 ? fmt::format(", IMU {}", imu) : "", why,
        one.Describe());
  }
  lines->push_back("taken out of every sample (the nine parameters will describe the sensor itself): " +
                   undo->description);
  source.SetUndo(lane, std::move(undo));
  return {};
}

}  // namespace

VehiclePreparation PrepareVehicleSource(MavlinkSource& source, VehicleCalibrationChoice choice,
                                        const mavlink::ParamExchange& exchange) {
  VehiclePreparation prep;
  for (std::size_t lane = 0; lane < source.imu_count(); ++lane) {
    const std::string refused = PrepareLane(source, lane, choice, exchange, &prep.lines);
    if (!refused.empty()) prep.refused += (prep.refused.empty() ? "" : "; ") + refused;
  }
  if (!prep.refused.empty())
    for (std::size_t lane = 0; lane < source.imu_count(); ++lane) source.SetUndo(lane, std::nullopt);
  prep.undone = choice == VehicleCalibrationChoice::kUndo && prep.refused.empty();
  return prep;
}

}  // namespace accelcal

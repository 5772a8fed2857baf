#include "accelcal/app/device/vehicle_session.h"

#include <fmt/format.h>

namespace accelcal {

VehiclePreparation PrepareVehicleSource(MavlinkSource& source, VehicleCalibrationChoice choice,
                                        const mavlink::ParamExchange& exchange) {
  VehiclePreparation prep;
  const VehicleAccelParams params = ReadVehicleAccelParams(source.connection(), source.spec().imu, exchange);
  prep.lines = DescribeVehicleAccelParams(params);
  if (choice == VehicleCalibrationChoice::kAsIs) {
    source.SetUndo(std::nullopt);
    prep.lines.push_back("left in the readings (as asked): the calibration will describe the sensor after "
                         "the vehicle's own correction, not the sensor itself");
    return prep;
  }
  std::string why;
  std::optional<mavlink::AccelUndo> undo = UndoOf(params, &why);
  if (!undo) {
    prep.refused = fmt::format(
        "{}: the vehicle's own calibration cannot be taken out of its readings: {}. Reset it on the "
        "vehicle (accelcal device-info --source {} --reset --apply writes offsets 0 and scales 1), or "
        "keep it knowingly (--vehicle-calibration as-is)",
        source.connection().LinkName(), why, source.Describe());
    return prep;
  }
  prep.lines.push_back("taken out of every sample (the nine parameters will describe the sensor itself): " +
                       undo->description);
  source.SetUndo(std::move(undo));
  prep.undone = true;
  return prep;
}

}  // namespace accelcal

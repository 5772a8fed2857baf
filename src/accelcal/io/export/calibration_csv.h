// Export of a calibration's parameters as CSV (RFC 4180: CRLF line ends, a field holding a
// comma, quote or line break is quoted with quotes doubled): a header `name,value,sigma,unit`,
// then one row per parameter: the nine of the model (sensor_model.h names and units: bias_x ..
// a_zx), each adopted effect's parameters as `EFFECT.PARAMETER` (e.g.
// `quadratic_nonlinearity.q_x`), then `gravity_mps2` and `residual_rms_mps2`. sigma is the
// 1-sigma uncertainty, empty where there is none. Values at full round-trip precision.
#pragma once

#include <string>

#include "accelcal/io/export/export_result.h"

namespace accelcal {

ExportResult ExportCalibrationCsv(const Calibration& cal);

}  // namespace accelcal

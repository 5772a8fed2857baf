// Export of a calibration as a C99 header for firmware: the correction as constants and one
// `static inline` function from raw counts to m/s^2.
//
//   a^p = M (raw' - b)    M = T K^-1 (sensor_model.h; m/s^2 per count), b counts
//
// raw' is the raw reading with the sensor's adopted effects removed, in apply's order
// (apply.h), each as the effect writes itself in C (Effect::InC, calibration/diagnosis/
// c_correction.h): its constants, and its statements inside the function. An effect that reads
// the temperature makes the function take the sensor's temperature, degC, as an extra argument;
// one that calls a function of <math.h> (the quadratic's sqrt) makes the header include it (link
// with -lm). The header therefore holds the whole calibration that `accelcal apply` applies:
// `cannot_hold` is empty; a sensor effect without a C form is refused by name (the export
// throws), and effects of the calibration session are listed in `notes` (apply ignores them too).
//
// In the header: ACCELCAL_REAL (default float; define it as double before including for double
// arithmetic), arrays `accelcal_bias_counts[3]`, `accelcal_correction_mps2_per_count[3][3]`
// (M, row-major), the effects' constants when adopted (in the library's order, effect.h), and
//   static inline void accelcal_correct(ACCELCAL_REAL raw_x, ..., [ACCELCAL_REAL temp_c,]
//                                       ACCELCAL_REAL out_mps2[3]);
// It compiles cleanly with `cc -std=c99 -Wall -Wextra -Werror -pedantic` (tested).
#pragma once

#include "accelcal/io/export/export_result.h"

namespace accelcal {

// Throws accelcal::Error for an effect this version does not know, a sensor effect without a C
// form (naming it), or a malformed effect.
ExportResult ExportCHeader(const Calibration& cal, const ExportContext& context);

}  // namespace accelcal

/* Accelerometer calibration by accelcal export-cal: device SIM-0001, calibrated 2025-03-01T14:05:09.000Z, from captures.csv.
 *
 *   a_p = M (raw' - b)   a_p: specific force in m/s^2, platform frame (x along the
 *                        sensor's x axis, y in the sensor's x-y plane, z completing a
 *                        right-handed frame); raw: ADC counts, axes x, y, z
 *   M = T K^-1           K = diag(scale), T = [[1, -a_yz, a_zy], [0, 1, -a_zx], [0, 0, 1]]
 *   raw' = raw with the sensor's effects removed, in this order: temperature_bias, temperature_scale, quadratic_nonlinearity
 *
 * Gravity used by the fit: 9.80665 m/s^2. Define ACCELCAL_REAL as double before including
 * this file for double arithmetic (default float).
 */
#ifndef ACCELCAL_CALIBRATION_H
#define ACCELCAL_CALIBRATION_H

#include <math.h>

#ifndef ACCELCAL_REAL
#define ACCELCAL_REAL float
#endif

/* b: bias (zero-g level), counts */
static const ACCELCAL_REAL accelcal_bias_counts[3] = {2051.25, 2043.5, 2039.75};
/* M = T K^-1, m/s^2 per count, row-major, from
   scale {34.1, 35.2, 34.6} counts per m/s^2 and
   a_yz 0.004, a_zy -0.003, a_zx 0.002 rad */
static const ACCELCAL_REAL accelcal_correction_mps2_per_count[3][3] = {
    {0.029325513196480937, -0.00011363636363636364, -8.670520231213873e-05},
    {0, 0.028409090909090908, -5.7803468208092484e-05},
    {0, 0, 0.028901734104046242}};
/* the nonlinear effects: K (counts per m/s^2) */
static const ACCELCAL_REAL accelcal_scale_counts_per_mps2[3] = {34.1, 35.2, 34.6};
/* quadratic_nonlinearity: q (counts per (m/s^2)^2) */
static const ACCELCAL_REAL accelcal_quadratic_counts_per_mps2_sq[3] = {0.02, -0.015, 0.01};
/* temperature effects: reference temperature, degC */
static const ACCELCAL_REAL accelcal_temp_ref_c = 25;
static const ACCELCAL_REAL accelcal_tc_bias_counts_per_degc[3] = {0.5, -0.3, 0.2};
static const ACCELCAL_REAL accelcal_tc_scale_per_degc[3] = {0.0001, -0.0002, 5e-05};

/* One reading: raw counts and the sensor's temperature temp_c (degC) -> out_mps2 = a_p, m/s^2. */
static inline void accelcal_correct(ACCELCAL_REAL raw_x, ACCELCAL_REAL raw_y, ACCELCAL_REAL raw_z, ACCELCAL_REAL temp_c,
                                    ACCELCAL_REAL out_mps2[3]) {
  const ACCELCAL_REAL(*m)[3] = accelcal_correction_mps2_per_count;
  ACCELCAL_REAL d[3];
  int j;
  const ACCELCAL_REAL dt_c = temp_c - accelcal_temp_ref_c;
  d[0] = raw_x - accelcal_bias_counts[0];
  d[1] = raw_y - accelcal_bias_counts[1];
  d[2] = raw_z - accelcal_bias_counts[2];
  /* temperature_bias: the zero-g level moves by tc counts per degC */
  for (j = 0; j < 3; ++j) d[j] -= accelcal_tc_bias_counts_per_degc[j] * dt_c;
  /* temperature_scale: the sensitivity is k (1 + tc dT) */
  for (j = 0; j < 3; ++j) d[j] /= (ACCELCAL_REAL)1 + accelcal_tc_scale_per_degc[j] * dt_c;
  /* quadratic_nonlinearity: d = k u + q u^2, solved for u (root near d/k) */
  for (j = 0; j < 3; ++j) {
    const ACCELCAL_REAL k = accelcal_scale_counts_per_mps2[j];
    const ACCELCAL_REAL disc = k * k + 4 * accelcal_quadratic_counts_per_mps2_sq[j] * d[j];
    if (disc > 0) d[j] = k * (2 * d[j] / (k + (ACCELCAL_REAL)sqrt((double)disc)));
  }
  out_mps2[0] = m[0][0] * d[0] + m[0][1] * d[1] + m[0][2] * d[2];
  out_mps2[1] = m[1][0] * d[0] + m[1][1] * d[1] + m[1][2] * d[2];
  out_mps2[2] = m[2][0] * d[0] + m[2][1] * d[1] + m[2][2] * d[2];
}

#endif /* ACCELCAL_CALIBRATION_H */

#include "accelcal/io/export/c_header.h"

#include <algorithm>
#include <iterator>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace accelcal {
namespace {

constexpr const char* kAxisSuffixes[3] = {"x", "y", "z"};

// "{a, b, c}" with each value written so that it reads back exactly as a double.
std::string Triple(double a, double b, double c) {
  return fmt::format("{{{}, {}, {}}}", ExportNumber(a), ExportNumber(b), ExportNumber(c));
}

std::string Triple(const Eigen::Vector3d& v) { return Triple(v.x(), v.y(), v.z()); }

Eigen::Vector3d EffectTriple(const Calibration& cal, const std::string& name, const std::string& prefix) {
  Eigen::Vector3d v;
  for (int j = 0; j < 3; ++j) v(j) = EffectParameterValue(cal, name, fmt::format("{}_{}", prefix, kAxisSuffixes[j]));
  return v;
}

// `text` (one line already: DescribeOrigin) safe inside a C block comment: "*/" would end the
// comment and let the rest compile as code, "/*" inside a comment is a warning (-Wcomment, an
// error under -Werror), and "??" could start a trigraph (C99 translation phase 1).
std::string InsideCComment(std::string_view text) {
  std::string out;
  for (char c : text) {
    const char before = out.empty() ? ' ' : out.back();
    if ((before == '*' && c == '/') || (before == '/' && c == '*') || (before == '?' && c == '?')) out += ' ';
    out += c;
  }
  return out;
}

bool Has(const std::vector<std::string>& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The per-axis statements of one effect inside the function (on d = raw - b, counts).
std::string EffectCode(const std::string& name) {
  if (name == "temperature_bias")
    return "  /* temperature_bias: the zero-g level moves by tc counts per degC */\n"
           "  for (j = 0; j < 3; ++j) d[j] -= accelcal_tc_bias_counts_per_degc[j] * dt_c;\n";
  if (name == "temperature_scale")
    return "  /* temperature_scale: the sensitivity is k (1 + tc dT) */\n"
           "  for (j = 0; j < 3; ++j) d[j] /= (ACCELCAL_REAL)1 + accelcal_tc_scale_per_degc[j] * dt_c;\n";
  if (name == "cubic_nonlinearity")
    return "  /* cubic_nonlinearity: d = k u + c3 u^3, solved for u by Newton from d/k */\n"
           "  for (j = 0; j < 3; ++j) {\n"
           "    const ACCELCAL_REAL k = accelcal_scale_counts_per_mps2[j];\n"
           "    const ACCELCAL_REAL c3 = accelcal_cubic_counts_per_mps2_cu[j];\n"
           "    ACCELCAL_REAL u = d[j] / k;\n"
           "    int it;\n"
           "    for (it = 0; it < 4; ++it) {\n"
           "      const ACCELCAL_REAL slope = k + 3 * c3 * u * u;\n"
           "      if (!(slope * slope > (ACCELCAL_REAL)0.01 * k * k)) break;\n"
           "      u -= (k * u + c3 * u * u * u - d[j]) / slope;\n"
           "    }\n"
           "    d[j] = k * u;\n"
           "  }\n";
  if (name == "cross_axis_coupling")
    return "  /* cross_axis_coupling: each axis also reads kappa/3 times the product of the other two\n"
           "     inputs (a magnitude fit sees only the sum kappa: shared equally) */\n"
           "  {\n"
           "    ACCELCAL_REAL u[3];\n"
           "    for (j = 0; j < 3; ++j) u[j] = d[j] / accelcal_scale_counts_per_mps2[j];\n"
           "    d[0] -= accelcal_scale_counts_per_mps2[0] * accelcal_cross_kappa_per_mps2 / 3 * u[1] * u[2];\n"
           "    d[1] -= accelcal_scale_counts_per_mps2[1] * accelcal_cross_kappa_per_mps2 / 3 * u[2] * u[0];\n"
           "    d[2] -= accelcal_scale_counts_per_mps2[2] * accelcal_cross_kappa_per_mps2 / 3 * u[0] * u[1];\n"
           "  }\n";
  // quadratic_nonlinearity: d = k u + q u^2; u is the root near d / k, in the form that stays
  // accurate as q -> 0.
  return "  /* quadratic_nonlinearity: d = k u + q u^2, solved for u (root near d/k) */\n"
         "  for (j = 0; j < 3; ++j) {\n"
         "    const ACCELCAL_REAL k = accelcal_scale_counts_per_mps2[j];\n"
         "    const ACCELCAL_REAL disc = k * k + 4 * accelcal_quadratic_counts_per_mps2_sq[j] * d[j];\n"
         "    if (disc > 0) d[j] = k * (2 * d[j] / (k + (ACCELCAL_REAL)sqrt((double)disc)));\n"
         "  }\n";
}

}  // namespace

ExportResult ExportCHeader(const Calibration& cal, const ExportContext& context) {
  const std::vector<std::string> effects = SensorEffectNames(cal);
  const bool temperature = Has(effects, "temperature_bias") || Has(effects, "temperature_scale");
  const bool quadratic = Has(effects, "quadratic_nonlinearity");
  const bool cubic = Has(effects, "cubic_nonlinearity");
  const bool cross = Has(effects, "cross_axis_coupling");
  const SensorModel& m = cal.model;
  const Eigen::Matrix3d M = CorrectionMatrix(m);

  ExportResult result;
  result.notes = SessionEffectNotes(cal);
  fmt::memory_buffer out;
  auto put = [&out](const std::string& s) { out.append(s.data(), s.data() + s.size()); };

  put(fmt::format(
      "/* Accelerometer calibration by accelcal export-cal: {}.\n"
      " *\n"
      " *   a_p = M (raw' - b)   a_p: specific force in m/s^2, platform frame (x along the\n"
      " *                        sensor's x axis, y in the sensor's x-y plane, z completing a\n"
      " *                        right-handed frame); raw: ADC counts, axes x, y, z\n"
      " *   M = T K^-1           K = diag(scale), T = [[1, -a_yz, a_zy], [0, 1, -a_zx], [0, 0, 1]]\n"
      " *   raw' = raw with the sensor's effects removed, in this order: {}\n"
      " *\n"
      " * Gravity used by the fit: {} m/s^2. Define ACCELCAL_REAL as double before including\n"
      " * this file for double arithmetic (default float).\n"
      " */\n",
      InsideCComment(DescribeOrigin(cal, context)), effects.empty() ? std::string("none") : fmt::format("{}", fmt::join(effects, ", ")),
      ExportNumber(cal.gravity.gravity_mps2)));
  put("#ifndef ACCELCAL_CALIBRATION_H\n#define ACCELCAL_CALIBRATION_H\n\n");
  if (quadratic) put("#include <math.h>\n\n");
  put("#ifndef ACCELCAL_REAL\n#define ACCELCAL_REAL float\n#endif\n\n");
  put(fmt::format("/* b: bias (zero-g level), counts */\nstatic const ACCELCAL_REAL accelcal_bias_counts[3] = {};\n",
                  Triple(m.bias_counts)));
  put(fmt::format("/* M = T K^-1, m/s^2 per count, row-major, from\n"
                  "   scale {} counts per m/s^2 and\n"
                  "   a_yz {}, a_zy {}, a_zx {} rad */\n"
                  "static const ACCELCAL_REAL accelcal_correction_mps2_per_count[3][3] = {{\n"
                  "    {},\n    {},\n    {}}};\n",
                  Triple(m.scale_counts_per_mps2), ExportNumber(m.a_yz_rad), ExportNumber(m.a_zy_rad),
                  ExportNumber(m.a_zx_rad), Triple(M.row(0).transpose()), Triple(M.row(1).transpose()),
                  Triple(M.row(2).transpose())));
  if (quadratic || cubic || cross)
    put(fmt::format("/* the nonlinear effects: K (counts per m/s^2) */\n"
                    "static const ACCELCAL_REAL accelcal_scale_counts_per_mps2[3] = {};\n",
                    Triple(m.scale_counts_per_mps2)));
  if (quadratic)
    put(fmt::format("/* quadratic_nonlinearity: q (counts per (m/s^2)^2) */\n"
                    "static const ACCELCAL_REAL accelcal_quadratic_counts_per_mps2_sq[3] = {};\n",
                    Triple(EffectTriple(cal, "quadratic_nonlinearity", "q"))));
  if (cubic)
    put(fmt::format("/* cubic_nonlinearity: c3 (counts per (m/s^2)^3) */\n"
                    "static const ACCELCAL_REAL accelcal_cubic_counts_per_mps2_cu[3] = {};\n",
                    Triple(EffectTriple(cal, "cubic_nonlinearity", "c3"))));
  if (cross)
    put(fmt::format("/* cross_axis_coupling: kappa (per m/s^2) */\n"
                    "static const ACCELCAL_REAL accelcal_cross_kappa_per_mps2 = {};\n",
                    ExportNumber(EffectParameterValue(cal, "cross_axis_coupling", "kappa"))));
  if (temperature) {
    put(fmt::format("/* temperature effects: reference temperature, degC */\n"
                    "static const ACCELCAL_REAL accelcal_temp_ref_c = {};\n",
                    ExportNumber(EffectReferenceTempC(cal))));
    if (Has(effects, "temperature_bias"))
      put(fmt::format("static const ACCELCAL_REAL accelcal_tc_bias_counts_per_degc[3] = {};\n",
                      Triple(EffectTriple(cal, "temperature_bias", "tc_bias"))));
    if (Has(effects, "temperature_scale"))
      put(fmt::format("static const ACCELCAL_REAL accelcal_tc_scale_per_degc[3] = {};\n",
                      Triple(EffectTriple(cal, "temperature_scale", "tc_scale"))));
  }
  put(fmt::format("\n/* One reading: raw counts{} -> out_mps2 = a_p, m/s^2. */\n"
                  "static inline void accelcal_correct(ACCELCAL_REAL raw_x, ACCELCAL_REAL raw_y, "
                  "ACCELCAL_REAL raw_z,{}\n"
                  "                                    ACCELCAL_REAL out_mps2[3]) {{\n",
                  temperature ? " and the sensor's temperature temp_c (degC)" : "",
                  temperature ? " ACCELCAL_REAL temp_c," : ""));
  put("  const ACCELCAL_REAL(*m)[3] = accelcal_correction_mps2_per_count;\n  ACCELCAL_REAL d[3];\n");
  if (!effects.empty()) put("  int j;\n");
  if (temperature) put("  const ACCELCAL_REAL dt_c = temp_c - accelcal_temp_ref_c;\n");
  put("  d[0] = raw_x - accelcal_bias_counts[0];\n"
      "  d[1] = raw_y - accelcal_bias_counts[1];\n"
      "  d[2] = raw_z - accelcal_bias_counts[2];\n");
  for (const std::string& name : effects) put(EffectCode(name));
  put("  out_mps2[0] = m[0][0] * d[0] + m[0][1] * d[1] + m[0][2] * d[2];\n"
      "  out_mps2[1] = m[1][0] * d[0] + m[1][1] * d[1] + m[1][2] * d[2];\n"
      "  out_mps2[2] = m[2][0] * d[0] + m[2][1] * d[1] + m[2][2] * d[2];\n"
      "}\n\n#endif /* ACCELCAL_CALIBRATION_H */\n");
  result.text = fmt::to_string(out);
  if (temperature)
    result.notes.push_back("accelcal_correct takes the sensor's temperature (degC): the calibration "
                           "corrects for temperature");
  if (quadratic) result.notes.push_back("the header uses sqrt from <math.h>: link with -lm");
  return result;
}

}  // namespace accelcal

#include "accelcal/io/export/c_header.h"

#include <algorithm>
#include <iterator>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accelcal/base/error.h"
#include "accelcal/calibration/diagnosis/effect.h"

namespace accelcal {
namespace {

// "{a, b, c}" with each value written so that it reads back exactly as a double.
std::string CArrayOf(const std::vector<double>& values) {
  std::vector<std::string> texts;
  for (double v : values) texts.push_back(ExportNumber(v));
  return fmt::format("{{{}}}", fmt::join(texts, ", "));
}

std::string CArrayOf(const Eigen::Vector3d& v) { return CArrayOf(std::vector<double>{v.x(), v.y(), v.z()}); }

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

// An adopted effect of the sensor with its C form (c_correction.h).
struct CarriedEffect {
  const Effect* effect;
  CCorrection c;
};

// The calibration's effects of the sensor, in correction order, each with its C form; throws,
// naming it, for one that has none.
std::vector<CarriedEffect> CarriedEffects(const Calibration& cal) {
  std::vector<CarriedEffect> carried;
  for (const std::string& name : SensorEffectNames(cal)) {
    const Effect* effect = FindEffect(name);
    std::optional<CCorrection> c = effect->InC();
    if (!c)
      throw Error(fmt::format("the C header cannot carry the effect '{}' ({}): this version of "
                              "accelcal has no C form for it, and a header without it would not "
                              "correct readings as `accelcal apply` does (export its parameters "
                              "with --to csv, or correct the readings with accelcal apply)",
                              name, effect->Story()));
    carried.push_back({effect, std::move(*c)});
  }
  return carried;
}

// `carried` in the order of the known effects (effect.h KnownEffects: the library's order), the
// order the header declares their constants in.
std::vector<const CarriedEffect*> InLibraryOrder(const std::vector<CarriedEffect>& carried) {
  std::vector<const CarriedEffect*> ordered;
  for (const Effect* known : KnownEffects())
    for (const CarriedEffect& c : carried)
      if (c.effect == known) ordered.push_back(&c);
  return ordered;
}

bool AnyReadsTemperature(const std::vector<CarriedEffect>& carried) {
  return std::any_of(carried.begin(), carried.end(), [](const CarriedEffect& c) { return c.effect->ReadsTemperature(); });
}

// The functions of <math.h> the effects call, each once, in the order first called.
std::vector<std::string> MathFunctions(const std::vector<CarriedEffect>& carried) {
  std::vector<std::string> functions;
  for (const CarriedEffect& c : carried)
    for (const std::string& f : c.c.math_functions)
      if (std::find(functions.begin(), functions.end(), f) == functions.end()) functions.push_back(f);
  return functions;
}

// The constants of the effects, each after the shared ones it reads (K, the reference
// temperature), which come once, before the first effect that reads them.
std::string EffectConstants(const Calibration& cal, const std::vector<CarriedEffect>& carried) {
  std::string out;
  bool scale_declared = false, temp_ref_declared = false;
  for (const CarriedEffect* c : InLibraryOrder(carried)) {
    if (c->c.reads_scale && !scale_declared) {
      out += fmt::format("/* the nonlinear effects: K (counts per m/s^2) */\n"
                         "static const ACCELCAL_REAL accelcal_scale_counts_per_mps2[3] = {};\n",
                         CArrayOf(cal.model.scale_counts_per_mps2));
      scale_declared = true;
    }
    if (c->effect->ReadsTemperature() && !temp_ref_declared) {
      out += fmt::format("/* temperature effects: reference temperature, degC */\n"
                         "static const ACCELCAL_REAL accelcal_temp_ref_c = {};\n",
                         ExportNumber(EffectReferenceTempC(cal)));
      temp_ref_declared = true;
    }
    const std::string name(c->effect->Name());
    for (const CCorrection::Constant& k : c->c.constants) {
      std::vector<double> values;
      for (const std::string& parameter : k.parameters) values.push_back(EffectParameterValue(cal, name, parameter));
      if (!k.comment.empty()) out += "/* " + k.comment + " */\n";
      out += values.size() == 1
                 ? fmt::format("static const ACCELCAL_REAL {} = {};\n", k.identifier, ExportNumber(values[0]))
                 : fmt::format("static const ACCELCAL_REAL {}[{}] = {};\n", k.identifier, values.size(), CArrayOf(values));
    }
  }
  return out;
}

}  // namespace

ExportResult ExportCHeader(const Calibration& cal, const ExportContext& context) {
  const std::vector<std::string> effects = SensorEffectNames(cal);
  const std::vector<CarriedEffect> carried = CarriedEffects(cal);
  const bool temperature = AnyReadsTemperature(carried);
  const std::vector<std::string> math = MathFunctions(carried);
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
  if (!math.empty()) put("#include <math.h>\n\n");
  put("#ifndef ACCELCAL_REAL\n#define ACCELCAL_REAL float\n#endif\n\n");
  put(fmt::format("/* b: bias (zero-g level), counts */\nstatic const ACCELCAL_REAL accelcal_bias_counts[3] = {};\n",
                  CArrayOf(m.bias_counts)));
  put(fmt::format("/* M = T K^-1, m/s^2 per count, row-major, from\n"
                  "   scale {} counts per m/s^2 and\n"
                  "   a_yz {}, a_zy {}, a_zx {} rad */\n"
                  "static const ACCELCAL_REAL accelcal_correction_mps2_per_count[3][3] = {{\n"
                  "    {},\n    {},\n    {}}};\n",
                  CArrayOf(m.scale_counts_per_mps2), ExportNumber(m.a_yz_rad), ExportNumber(m.a_zy_rad),
                  ExportNumber(m.a_zx_rad), CArrayOf(M.row(0).transpose()), CArrayOf(M.row(1).transpose()),
                  CArrayOf(M.row(2).transpose())));
  put(EffectConstants(cal, carried));
  put(fmt::format("\n/* One reading: raw counts{} -> out_mps2 = a_p, m/s^2. */\n"
                  "static inline void accelcal_correct(ACCELCAL_REAL raw_x, ACCELCAL_REAL raw_y, "
                  "ACCELCAL_REAL raw_z,{}\n"
                  "                                    ACCELCAL_REAL out_mps2[3]) {{\n",
                  temperature ? " and the sensor's temperature temp_c (degC)" : "",
                  temperature ? " ACCELCAL_REAL temp_c," : ""));
  put("  const ACCELCAL_REAL(*m)[3] = accelcal_correction_mps2_per_count;\n  ACCELCAL_REAL d[3];\n");
  if (!carried.empty()) put("  int j;\n");
  if (temperature) put("  const ACCELCAL_REAL dt_c = temp_c - accelcal_temp_ref_c;\n");
  put("  d[0] = raw_x - accelcal_bias_counts[0];\n"
      "  d[1] = raw_y - accelcal_bias_counts[1];\n"
      "  d[2] = raw_z - accelcal_bias_counts[2];\n");
  for (const CarriedEffect& c : carried) put(c.c.statements);
  put("  out_mps2[0] = m[0][0] * d[0] + m[0][1] * d[1] + m[0][2] * d[2];\n"
      "  out_mps2[1] = m[1][0] * d[0] + m[1][1] * d[1] + m[1][2] * d[2];\n"
      "  out_mps2[2] = m[2][0] * d[0] + m[2][1] * d[1] + m[2][2] * d[2];\n"
      "}\n\n#endif /* ACCELCAL_CALIBRATION_H */\n");
  result.text = fmt::to_string(out);
  if (temperature)
    result.notes.push_back("accelcal_correct takes the sensor's temperature (degC): the calibration "
                           "corrects for temperature");
  if (!math.empty())
    result.notes.push_back(fmt::format("the header uses {} from <math.h>: link with -lm", fmt::join(math, ", ")));
  return result;
}

}  // namespace accelcal

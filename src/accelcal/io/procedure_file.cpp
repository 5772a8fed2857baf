#include "accelcal/io/procedure_file.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/core.h>
#include <toml++/toml.h>

#include "accelcal/base/error.h"
#include "accelcal/io/detail/read_file.h"
#include "accelcal/io/detail/toml_reader.h"

namespace accelcal {
namespace {

using detail::NumberRange;
using detail::TomlTableReader;

void ReadSensor(TomlTableReader& r, Procedure& p) {
  p.range_g = r.Number("range_g", 6.0, NumberRange::kPositive);
  const double scale = r.Number("nominal_scale_counts_per_mps2", std::nullopt, NumberRange::kPositive);
  const double bias = r.Number("nominal_bias_counts", std::nullopt);
  p.nominal.scale_counts_per_mps2 = Eigen::Vector3d::Constant(scale);
  p.nominal.bias_counts = Eigen::Vector3d::Constant(bias);
  const std::int64_t bits = r.Integer("adc_bits", 12);
  if (bits < 1 || bits > 32) r.Fail(*r.Get("adc_bits"), "adc_bits", "must be 1..32");
  const bool is_signed = r.Bool("adc_signed", false);
  const double span = std::ldexp(1.0, static_cast<int>(bits));
  p.adc_range = is_signed ? AdcRange{-span / 2, span / 2 - 1} : AdcRange{0.0, span - 1};
}

StepDefaults ReadChecks(TomlTableReader& r, Procedure& p) {
  StepDefaults d;
  d.duration_s = r.Number("capture_duration_s", 10.0, NumberRange::kPositive);
  d.timeout_s = r.Number("capture_timeout_s", 60.0, NumberRange::kPositive);
  p.orientation_tolerance_deg = r.Number("orientation_tolerance_deg", 15.0, NumberRange::kPositive);
  p.std_multiplier = r.Number("std_multiplier", 1.5, NumberRange::kPositive);
  p.trend_multiplier = r.Number("trend_multiplier", 2.0, NumberRange::kPositive);
  p.turntable_tolerance = r.Number("turntable_tolerance", 0.10, NumberRange::kPositive);
  p.turntable_tilt_tolerance_deg = r.Number("turntable_tilt_tolerance_deg",
                                            p.turntable_tilt_tolerance_deg, NumberRange::kPositive);
  if (const toml::node* node = r.Get("expected_noise_counts")) {
    // One number for every axis, or [x, y, z].
    p.expected_noise_counts = node->is_array()
                                  ? r.Vector3("expected_noise_counts", std::nullopt, NumberRange::kPositive)
                                  : Eigen::Vector3d::Constant(r.Number("expected_noise_counts", std::nullopt,
                                                                       NumberRange::kPositive));
  }
  p.noise_floor_max_ratio = r.Number("noise_floor_max_ratio", p.noise_floor_max_ratio, NumberRange::kPositive);
  if (!(p.noise_floor_max_ratio > 1.0))
    r.Fail(*r.Get("noise_floor_max_ratio"), "noise_floor_max_ratio", "must be above 1");
  return d;
}

// A limit on U (k = 2) under its key, or under the first format's 1-sigma key read by the
// stated rule: U = 2 x the 1-sigma (ProcedureLimits says why). Both keys at once is refused.
double ReadULimit(TomlTableReader& r, std::string_view u_key, std::string_view sigma_key,
                  ProcedureLimits& l) {
  const double u = r.Number(u_key, kNaN, NumberRange::kPositive);
  const double sigma = r.Number(sigma_key, kNaN, NumberRange::kPositive);
  if (std::isnan(sigma)) return u;
  if (!std::isnan(u))
    r.Fail(*r.Get(sigma_key), sigma_key,
           fmt::format("give {} (U, k = 2) or the older {} (1-sigma), not both", u_key, sigma_key));
  l.converted.push_back(fmt::format("{} = {:g} (1-sigma) read as {} = {:g} (U, k = 2)", sigma_key,
                                    sigma, u_key, 2.0 * sigma));
  return 2.0 * sigma;
}

ProcedureLimits ReadLimits(TomlTableReader& r) {
  ProcedureLimits l;
  l.max_residual_rms_mps2 = r.Number("max_residual_rms_mps2", kNaN, NumberRange::kPositive);
  l.max_residual_rms_noise = r.Number("max_residual_rms_noise", kNaN, NumberRange::kPositive);
  l.max_bias_U_counts = ReadULimit(r, "max_bias_U_counts", "max_bias_sigma_counts", l);
  l.max_scale_U_ppm = ReadULimit(r, "max_scale_U_ppm", "max_scale_sigma_ppm", l);
  l.max_misalignment_U_rad = ReadULimit(r, "max_misalignment_U_rad", "max_misalignment_sigma_rad", l);
  l.bias_tolerance_counts = r.Number("bias_tolerance_counts", kNaN, NumberRange::kPositive);
  l.scale_tolerance_percent = r.Number("scale_tolerance_percent", kNaN, NumberRange::kPositive);
  l.misalignment_tolerance_rad = r.Number("misalignment_tolerance_rad", kNaN, NumberRange::kPositive);
  const std::string rule = r.String("decision_rule", std::string(DecisionRuleKey(l.decision_rule)));
  const std::optional<DecisionRule> decision = DecisionRuleFromKey(rule);
  if (!decision)
    r.Fail(*r.Get("decision_rule"), "decision_rule",
           "'" + rule + "' is not a decision rule: \"simple\" (simple acceptance) or \"guard_band\" "
           "(guarded acceptance, w = U)");
  l.decision_rule = *decision;
  const std::int64_t n = r.Integer("min_captures", 0);
  if (n < 0 || n > 100000) r.Fail(*r.Get("min_captures"), "min_captures", "must be 0..100000");
  l.min_captures = static_cast<int>(n);
  return l;
}

// [target]: the U(k=2) the plan aims for, the longest capture and the bench's handling times;
// a target looser than [limits] is refused at its key (read after [limits] and [sensor]).
ProcedureTarget ReadTarget(TomlTableReader& r, const Procedure& p) {
  ProcedureTarget t;
  t.bias_mg = r.Number("bias_mg", kNaN, NumberRange::kPositive);
  t.scale_ppm = r.Number("scale_ppm", kNaN, NumberRange::kPositive);
  t.misalignment_mrad = r.Number("misalignment_mrad", kNaN, NumberRange::kPositive);
  t.max_capture_s = r.Number("max_capture_s", t.max_capture_s, NumberRange::kPositive);
  t.pose_handling_s = r.Number("pose_handling_s", t.pose_handling_s, NumberRange::kNonNegative);
  t.mounting_s = r.Number("mounting_s", t.mounting_s, NumberRange::kNonNegative);
  if (const TargetConflict c = CheckTargetAgainstLimits(t, p.limits, p.nominal); !c.key.empty())
    r.FailKey(c.key, c.message);
  return t;
}

ProcedureRequirements ReadRequirements(TomlTableReader& r) {
  ProcedureRequirements q;
  q.device_serial = r.Bool("device_serial", false);
  q.operator_name = r.Bool("operator", false);
  q.local_gravity = r.Bool("local_gravity", false);
  return q;
}

// [equipment]: one sub-table per role ([equipment.ruler], ...), each with its name, id,
// uncertainty (in the file's unit) and traceability; an unknown role is refused.
std::vector<EquipmentItem> ReadEquipment(TomlTableReader& r, const std::string& source) {
  std::vector<EquipmentItem> items;
  for (const EquipmentRoleInfo& info : EquipmentRoles()) {
    const toml::table* table = r.Table(info.key);
    if (table == nullptr) continue;
    TomlTableReader t(*table, "equipment." + std::string(info.key), source);
    EquipmentItem item;
    item.role = info.role;
    item.name = t.String("name", std::string(info.key));
    item.identification = t.String("id", std::string());
    item.standard_uncertainty = t.Number(info.uncertainty_key, kNaN, NumberRange::kNonNegative) * info.to_si;
    item.traceability = t.String("traceability", std::string());
    item.calibration = t.String("calibration", std::string());
    t.Finish();
    items.push_back(std::move(item));
  }
  return items;
}

// A step's fields read from its TOML table, for its kind's reader (session/step_kind.h).
class TomlStepFields final : public StepFields {
 public:
  explicit TomlStepFields(TomlTableReader& r) : r_(r) {}
  bool Has(std::string_view key) const override { return r_.Has(key); }
  double Number(std::string_view key, std::optional<double> fallback, FieldRange range) override {
    return r_.Number(key, fallback, range == FieldRange::kPositive      ? NumberRange::kPositive
                                    : range == FieldRange::kNonNegative ? NumberRange::kNonNegative
                                                                        : NumberRange::kAny);
  }
  std::string Text(std::string_view key, std::optional<std::string> fallback) override {
    return r_.String(key, std::move(fallback));
  }
  Eigen::Vector3d Vector3(std::string_view key, std::optional<Eigen::Vector3d> fallback) override {
    return r_.Vector3(key, fallback);
  }
  [[noreturn]] void Fail(std::string_view key, const std::string& message) const override {
    r_.FailKey(key, message);
  }

 private:
  TomlTableReader& r_;
};

// "level, static, ... or analysis": the kinds the table knows.
std::string KindChoices() {
  const std::vector<std::string_view> names = StepKindNames();
  std::string text;
  for (size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(names[i]);
  return text;
}

// The fields every step has, and its kind's own (its kind reads them: session/step_kind.h).
ProcedureStep ReadStep(TomlTableReader& r, const StepDefaults& d) {
  ProcedureStep s;
  s.id = r.String("id", std::nullopt);
  if (s.id.empty()) r.Fail(*r.Get("id"), "id", "must not be empty");
  const std::string kind = r.String("kind", std::nullopt);
  const std::optional<StepKind> k = StringToStepKind(kind);
  if (!k) r.Fail(*r.Get("kind"), "kind", "'" + kind + "' is not a step kind: expected " + KindChoices());
  s.kind = *k;
  const StepKindInfo& info = InfoOf(s.kind);
  TomlStepFields fields(r);
  if (info.read_fields != nullptr) info.read_fields(fields, s, d);
  s.title = r.String("title", s.pose_name.empty() ? std::string(info.name) : s.pose_name);
  s.required = r.Bool("required", true);
  if (!info.fixed_pose.empty()) s.pose_name = std::string(info.fixed_pose);
  return s;
}

template <typename Fn>
void WithTable(TomlTableReader& root, std::string_view key, const std::string& source, Fn&& fn) {
  const toml::table* table = root.Table(key);
  if (table == nullptr) return;
  TomlTableReader reader(*table, std::string(key), source);
  fn(reader);
  reader.Finish();
}

void ReadSteps(TomlTableReader& root, const StepDefaults& d, const std::string& source,
               Procedure& p) {
  const toml::array* steps = root.ArrayOfTables("step");
  if (steps == nullptr || steps->empty())
    throw InputError(source, 0, 0, "the procedure has no [[step]]");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < steps->size(); ++i) {
    const toml::table& table = *steps->get(i)->as_table();
    TomlTableReader r(table, fmt::format("step {}", i + 1), source);
    ProcedureStep s = ReadStep(r, d);
    r.Finish();
    if (!ids.insert(s.id).second) r.Fail(*r.Get("id"), "id", "'" + s.id + "' is used twice");
    if (const auto check = InfoOf(s.kind).check_order) {
      TomlStepFields fields(r);
      check(s, p.steps, fields);
    }
    p.steps.push_back(std::move(s));
  }
}

// former_titles: an array of strings (absent: none).
std::vector<std::string> ReadFormerTitles(TomlTableReader& root) {
  std::vector<std::string> titles;
  const toml::node* node = root.Get("former_titles");
  if (node == nullptr) return titles;
  const toml::array* array = node->as_array();
  if (array == nullptr) root.Fail(*node, "former_titles", "must be an array of strings");
  for (const toml::node& item : *array) {
    const toml::value<std::string>* text = item.as_string();
    if (text == nullptr) root.Fail(item, "former_titles", "must be an array of strings");
    titles.push_back(text->get());
  }
  return titles;
}

}  // namespace

Procedure ParseProcedure(std::string_view toml_text, const std::string& source_name) {
  const toml::table doc = detail::ParseTomlDocument(toml_text, source_name);
  Procedure p;
  p.source_name = source_name;
  TomlTableReader root(doc, "", source_name);
  p.title = root.String("title", std::nullopt);
  p.former_titles = ReadFormerTitles(root);
  bool has_sensor = false;
  WithTable(root, "sensor", source_name, [&](TomlTableReader& r) {
    ReadSensor(r, p);
    has_sensor = true;
  });
  if (!has_sensor) throw InputError(source_name, 0, 0, "required table [sensor] is missing");
  StepDefaults defaults;
  WithTable(root, "checks", source_name,
            [&](TomlTableReader& r) { defaults = ReadChecks(r, p); });
  WithTable(root, "limits", source_name, [&](TomlTableReader& r) { p.limits = ReadLimits(r); });
  WithTable(root, "target", source_name, [&](TomlTableReader& r) { p.target = ReadTarget(r, p); });
  WithTable(root, "requirements", source_name,
            [&](TomlTableReader& r) { p.requirements = ReadRequirements(r); });
  WithTable(root, "equipment", source_name,
            [&](TomlTableReader& r) { p.equipment = ReadEquipment(r, source_name); });
  ReadSteps(root, defaults, source_name, p);
  root.Finish();
  return p;
}

Procedure LoadProcedure(const std::string& path) {
  return ParseProcedure(detail::ReadWholeFile(path), path);
}

}  // namespace accelcal

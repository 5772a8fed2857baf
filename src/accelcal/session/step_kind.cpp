#include "accelcal/session/step_kind.h"

#include <algorithm>
#include <deque>

#include <Eigen/Geometry>
#include <fmt/core.h>

#include "accelcal/base/capture.h"
#include "accelcal/base/error.h"
#include "accelcal/session/procedure.h"

namespace accelcal {
namespace {

// ---- the kinds' own fields in the procedure file --------------------------------------------

SensorAxis ReadStepAxis(StepFields& f, std::string_view key, SensorAxis fallback) {
  const std::string text = f.Text(key, std::string(SensorAxisToString(fallback)));
  const std::optional<SensorAxis> axis = StringToSensorAxis(text);
  if (!axis) f.Fail(key, "'" + text + "' is not an axis: expected +x, -x, ... -z");
  return *axis;
}

void ReadStepPose(StepFields& f, ProcedureStep& s) {
  s.up = f.Vector3("up", Eigen::Vector3d::UnitZ());
  if (!(s.up.norm() > 0.0)) f.Fail("up", "must not be zero");
  s.up.normalize();
  s.pose_name = f.Text("pose", DescribeUp(s.up) + " up");
}

void ReadStepDurations(StepFields& f, ProcedureStep& s, const StepDefaults& d) {
  s.duration_s = f.Number("duration_s", d.duration_s, FieldRange::kPositive);
  // A long record gets a timeout beyond its own length by default.
  const double fallback = std::max(d.timeout_s, s.duration_s + d.timeout_s);
  s.timeout_s = f.Number("timeout_s", s.duration_s >= d.timeout_s ? fallback : d.timeout_s,
                         FieldRange::kPositive);
  if (s.timeout_s <= s.duration_s) {
    if (f.Has("timeout_s")) f.Fail("timeout_s", "must exceed duration_s");
    f.Fail("duration_s", "must be below the capture timeout");
  }
}

void ReadLevelFields(StepFields& f, ProcedureStep& s, const StepDefaults& d) {
  s.tolerance_deg = f.Number("tolerance_deg", 1.5, FieldRange::kPositive);
  s.duration_s = f.Number("duration_s", 3.0, FieldRange::kPositive);
  s.timeout_s = f.Number("timeout_s", d.timeout_s, FieldRange::kPositive);
}

void ReadStaticFields(StepFields& f, ProcedureStep& s, const StepDefaults& d) {
  ReadStepPose(f, s);
  ReadStepDurations(f, s, d);
}

void ReadRecordFields(StepFields& f, ProcedureStep& s, const StepDefaults& d) {
  ReadStepPose(f, s);
  ReadStepDurations(f, s, d);
  s.chunk_s = f.Number("chunk_s", ProcedureStep::kDefaultRecordChunkS, FieldRange::kPositive);
}

void ReadTurntableFields(StepFields& f, ProcedureStep& s, const StepDefaults& d) {
  s.radius_m = f.Number("radius_m", std::nullopt, FieldRange::kPositive);
  s.rpm = f.Number("rpm", std::nullopt, FieldRange::kPositive);
  s.radial_axis = ReadStepAxis(f, "radial", SensorAxis::kPlusX);
  s.up_axis = ReadStepAxis(f, "up_axis", SensorAxis::kPlusZ);
  if (SensorAxisVector(s.radial_axis).cross(SensorAxisVector(s.up_axis)).norm() < 0.5)
    f.Fail("radial", "must be perpendicular to up_axis");  // "radial" may be the default
  s.pose_name = fmt::format("{} radial, {} up", SensorAxisToString(s.radial_axis),
                            SensorAxisToString(s.up_axis));
  ReadStepDurations(f, s, d);
}

void ReadAnalysisFields(StepFields& f, ProcedureStep& s, const StepDefaults&) {
  s.record_step = f.Text("record", std::nullopt);
  s.method = f.Text("method", std::nullopt);
  if (s.method != "allan" && s.method != "noise")
    f.Fail("method", "'" + s.method + "' is not an analysis: expected allan or noise");
}

// An analysis reads an earlier record step.
void CheckAnalysisOrder(ProcedureStep& s, const std::vector<ProcedureStep>& earlier, StepFields& f) {
  const bool earlier_record = std::any_of(earlier.begin(), earlier.end(), [&](const ProcedureStep& e) {
    return e.id == s.record_step && IsRecordStep(e.kind);
  });
  if (!earlier_record) f.Fail("record", "'" + s.record_step + "' is not an earlier record step");
}

// ---- the table ------------------------------------------------------------------------------

// In StepKind's order: a kind's value is its row.
std::deque<StepKindInfo>& StepKindTable() {
  static std::deque<StepKindInfo> table = {
      {"level", StepAcquires::kReadings, true, false, "+z up", &ReadLevelFields, nullptr},
      {"static", StepAcquires::kStaticCapture, true, false, "", &ReadStaticFields, nullptr},
      {"turntable", StepAcquires::kTurntableCapture, true, false, "", &ReadTurntableFields, nullptr},
      {"record", StepAcquires::kRecord, true, false, "", &ReadRecordFields, nullptr},
      {"fit", StepAcquires::kNothing, false, false, "", nullptr, nullptr},
      {"diagnosis", StepAcquires::kNothing, true, false, "", nullptr, nullptr},
      {"report", StepAcquires::kNothing, false, true, "", nullptr, nullptr},
      {"analysis", StepAcquires::kNothing, true, false, "", &ReadAnalysisFields, &CheckAnalysisOrder},
  };
  return table;
}

const StepKindInfo* StepKindRow(StepKind kind) {
  const std::deque<StepKindInfo>& table = StepKindTable();
  const int i = static_cast<int>(kind);
  return i >= 0 && i < static_cast<int>(table.size()) ? &table[static_cast<size_t>(i)] : nullptr;
}

}  // namespace

const StepKindInfo& InfoOf(StepKind kind) {
  const StepKindInfo* row = StepKindRow(kind);
  if (row == nullptr) throw Error(fmt::format("step kind {} is not registered", static_cast<int>(kind)));
  return *row;
}

std::string_view StepKindToString(StepKind kind) {
  const StepKindInfo* row = StepKindRow(kind);
  return row != nullptr ? row->name : "?";
}

std::optional<StepKind> StringToStepKind(std::string_view text) {
  const std::deque<StepKindInfo>& table = StepKindTable();
  for (size_t i = 0; i < table.size(); ++i)
    if (table[i].name == text) return static_cast<StepKind>(i);
  return std::nullopt;
}

std::vector<std::string_view> StepKindNames() {
  std::vector<std::string_view> names;
  for (const StepKindInfo& row : StepKindTable()) names.push_back(row.name);
  return names;
}

StepKind RegisterStepKind(const StepKindInfo& info) {
  if (info.name.empty()) throw Error("a step kind needs a name");
  if (const std::optional<StepKind> known = StringToStepKind(info.name)) return *known;
  StepKindTable().push_back(info);
  return static_cast<StepKind>(StepKindTable().size() - 1);
}

bool UsesSensor(StepKind kind) { return InfoOf(kind).acquires != StepAcquires::kNothing; }

bool KeepsCapture(StepKind kind) {
  const StepAcquires a = InfoOf(kind).acquires;
  return a == StepAcquires::kStaticCapture || a == StepAcquires::kTurntableCapture;
}

bool KeepsData(StepKind kind) { return KeepsCapture(kind) || IsRecordStep(kind); }

bool IsRecordStep(StepKind kind) { return InfoOf(kind).acquires == StepAcquires::kRecord; }

bool IsStaticPoseStep(StepKind kind) { return InfoOf(kind).acquires == StepAcquires::kStaticCapture; }

bool IsTurntableRunStep(StepKind kind) { return InfoOf(kind).acquires == StepAcquires::kTurntableCapture; }

}  // namespace accelcal

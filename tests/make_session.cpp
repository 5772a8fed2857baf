// accelcal_make_session: writes a finished session for the end-to-end tests (until the wizard
// makes them): the 18 simulated captures of the default scenario, one per step, the device and
// operator inputs, and the calibration from fitting them. With --noise, a session of the noise
// procedure instead: its `record` step's 60 s static record, z up, level, of the default
// scenario's sensor with OFFSETS (counts, "x,y,z") added to its bias, white noise only, seed
// SEED, the session's creation time backdated to DATE (YYYY-MM-DD, 09:00 UTC).
//
//   accelcal_make_session OUT.db --noise PROCEDURE.toml SERIAL DATE OFFSETS SEED
//   accelcal_make_session OUT.db [--no-result] [--device SERIAL] [--date ISO8601]
//                         [--bias-offset-counts X,Y,Z] [--scale-offset-counts-per-mps2 X,Y,Z]
//                         [--misalignment-offset-rad YZ,ZY,ZX]
//
// --device (default SIM-0001) and --date (the session's creation time, e.g.
// 2025-03-01T14:05:09.000Z; default now) set what `accelcal history` sorts and groups by. The
// offsets are added to the default scenario's true sensor, so a later session of the same
// device shows a known change (the noise is the same seed's: the fitted change is the offset).
#include <cstdio>
#include <cstring>
#include <exception>
#include <sstream>
#include <string>

#include <fmt/core.h>

#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/base/error.h"
#include "accelcal/calibration/fit/calibration_fit.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/io/detail/json_forms.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/session/detail/sqlite_db.h"
#include "accelcal/session/session_store.h"
#include "accelcal/session/procedure.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"

namespace {

struct MakeSessionOptions {
  std::string path;
  bool with_result = true;
  std::string device = "SIM-0001";
  std::string date_utc;  // empty: now
  Eigen::Vector3d bias_offset_counts = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale_offset_counts_per_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d misalignment_offset_rad = Eigen::Vector3d::Zero();  // yz, zy, zx
};

Eigen::Vector3d ParseTriple(const std::string& text) {
  Eigen::Vector3d v;
  char c1 = 0, c2 = 0;
  std::istringstream in(text);
  if (!(in >> v.x() >> c1 >> v.y() >> c2 >> v.z()) || c1 != ',' || c2 != ',' || !in.eof())
    throw accelcal::Error(fmt::format("'{}' is not X,Y,Z", text));
  return v;
}

// The store stamps "now"; the tests need sessions of other dates (history, day-to-day noise).
void Backdate(const std::string& path, const std::string& created_utc, const std::string& updated_utc) {
  accelcal::detail::SqliteDb db(path, false);
  accelcal::detail::SqliteStatement(db, "UPDATE session SET created_utc = ?, updated_utc = ? WHERE id = 1")
      .Bind(1, created_utc).Bind(2, updated_utc).Run();
}

void MakeSession(const MakeSessionOptions& o) {
  using namespace accelcal;
  sim::Scenario scenario = sim::DefaultScenario();
  SensorModel& truth = scenario.sensor.model;
  truth.bias_counts += o.bias_offset_counts;
  truth.scale_counts_per_mps2 += o.scale_offset_counts_per_mps2;
  truth.a_yz_rad += o.misalignment_offset_rad.x();
  truth.a_zy_rad += o.misalignment_offset_rad.y();
  truth.a_zx_rad += o.misalignment_offset_rad.z();
  sim::VirtualBench bench(scenario);
  const std::vector<Capture> captures = bench.SimulateCaptureSet();
  SessionOpenOptions options;
  options.procedure = "bench_default";
  options.source = "sim";
  {
    auto store = SessionStore::Open(o.path, options);
    store->RecordInput(kSessionStep, kDeviceKey, o.device);
    store->RecordInput(kSessionStep, kOperatorKey, "e2e");
    for (const Capture& c : captures) store->RecordCapture(fmt::format("capture_{}", c.id), c);
    if (o.with_result) {
      FitOptions fit;
      const FitSummary summary = FitCalibration(captures, fit);
      if (!summary.IsUsable()) throw Error("the scenario did not fit: " + summary.message);
      store->RecordResult(CalibrationToJsonText(MakeCalibration(summary, fit.gravity, captures, o.path)));
      store->MarkDone();
    }
  }
  if (!o.date_utc.empty()) Backdate(o.path, o.date_utc, o.date_utc);
}

void MakeNoiseSession(const std::string& path, const std::string& procedure_path,
                      const std::string& serial, const std::string& date,
                      const std::string& offsets, const std::string& seed) {
  using namespace accelcal;
  const Procedure procedure = LoadProcedure(procedure_path);
  const ProcedureStep* record = nullptr;
  for (const ProcedureStep& step : procedure.steps)
    if (step.kind == StepKind::kRecord) record = &step;
  if (record == nullptr) throw Error(procedure_path + " has no record step");
  sim::Scenario s = sim::DefaultScenario();
  s.sensor.model.bias_counts += ParseTriple(offsets);
  s.bench.seed = std::stoull(seed);
  s.bench.placement_error_deg = 0.0;
  s.captures.resize(1);
  s.captures[0] = sim::CapturePlan{};
  s.captures[0].label = record->pose_name;
  s.captures[0].up = record->up;
  s.captures[0].duration_s = record->duration_s;
  const std::vector<Capture> captures = sim::VirtualBench(s).SimulateCaptureSet();
  {
    SessionOpenOptions options;
    options.procedure = procedure.title;
    options.source = "sim";
    auto store = SessionStore::Open(path, options);
    store->RecordInput(kSessionStep, kDeviceKey, serial);
    store->RecordInput(kSessionStep, kOperatorKey, "e2e");
    // As the wizard keeps a record step: chunks of the step's chunk_s (record_step_writer.h).
    long index = 0;
    RecordChunk chunk;
    for (const Sample& sample : captures[0].samples) {
      if (!chunk.samples.empty() && sample.t_s - chunk.samples.front().t_s >= record->chunk_s) {
        chunk.index = index++;
        store->AppendRecordChunk(record->id, chunk);
        chunk.samples.clear();
      }
      chunk.samples.push_back(sample);
    }
    chunk.index = index;
    store->AppendRecordChunk(record->id, chunk);
    store->RecordStepDone(record->id, "recorded");
    store->MarkDone();
  }
  // The analysis groups records by day.
  Backdate(path, date + "T09:00:00.000Z", date + "T09:01:00.000Z");
}

}  // namespace

int main(int argc, char** argv) {
  accelcal::RegisterStepKinds();  // before any procedure is read
  if (argc == 8 && std::strcmp(argv[2], "--noise") == 0) {
    try {
      MakeNoiseSession(argv[1], argv[3], argv[4], argv[5], argv[6], argv[7]);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "accelcal_make_session: %s\n", e.what());
      return 1;
    }
    return 0;
  }
  MakeSessionOptions o;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw accelcal::Error(arg + " needs a value");
        return argv[++i];
      };
      if (arg == "--no-result") o.with_result = false;
      else if (arg == "--device") o.device = value();
      else if (arg == "--date") o.date_utc = value();
      else if (arg == "--bias-offset-counts") o.bias_offset_counts = ParseTriple(value());
      else if (arg == "--scale-offset-counts-per-mps2") o.scale_offset_counts_per_mps2 = ParseTriple(value());
      else if (arg == "--misalignment-offset-rad") o.misalignment_offset_rad = ParseTriple(value());
      else if (o.path.empty() && arg.rfind("--", 0) != 0) o.path = arg;
      else throw accelcal::Error("unknown argument " + arg);
    }
    if (o.path.empty()) throw accelcal::Error("no output file");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accelcal_make_session: %s\nusage: accelcal_make_session OUT.db [--no-result] "
                 "[--device SERIAL] [--date ISO8601] [--bias-offset-counts X,Y,Z] "
                 "[--scale-offset-counts-per-mps2 X,Y,Z] [--misalignment-offset-rad YZ,ZY,ZX]\n", e.what());
    return 2;
  }
  try {
    MakeSession(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accelcal_make_session: %s\n", e.what());
    return 1;
  }
  return 0;
}

// accelcal_make_session: writes a finished session for the end-to-end tests (until the wizard
// makes them): the 18 simulated captures of the default scenario, one per step, the device and
// operator inputs, and the calibration from fitting them. With --noise, a session of the noise
// procedure instead: its `record` step's 60 s static record, z up, level, of the default
// scenario's sensor with OFFSETS (counts, "x,y,z") added to its bias, white noise only, seed
// SEED, the session's creation time backdated to DATE (YYYY-MM-DD, 09:00 UTC).
//
//   accelcal_make_session OUT.db [--no-result]
//   accelcal_make_session OUT.db --noise PROCEDURE.toml SERIAL DATE OFFSETS SEED
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include <fmt/core.h>

#include "accelcal/error.h"
#include "accelcal/fit/calibration_fit.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/session/detail/sqlite_db.h"
#include "accelcal/session/session_store.h"
#include "accelcal/wizard/procedure.h"
#include "accelcal/sim/scenario.h"
#include "accelcal/sim/virtual_bench.h"

namespace {

void MakeSession(const std::string& path, bool with_result) {
  using namespace accelcal;
  sim::VirtualBench bench(sim::DefaultScenario());
  const std::vector<Capture> captures = bench.SimulateCaptureSet();
  SessionOpenOptions options;
  options.procedure = "bench_default";
  options.source = "sim";
  auto store = SessionStore::Open(path, options);
  store->RecordInput(kSessionStep, kDeviceKey, "SIM-0001");
  store->RecordInput(kSessionStep, kOperatorKey, "e2e");
  for (const Capture& c : captures) store->RecordCapture(fmt::format("capture_{}", c.id), c);
  if (!with_result) return;
  FitOptions fit;
  const FitSummary summary = FitCalibration(captures, fit);
  if (!summary.IsUsable()) throw Error("the default scenario did not fit: " + summary.message);
  store->RecordResult(CalibrationToJson(MakeCalibration(summary, fit.gravity, captures, path)));
  store->MarkDone();
}

Eigen::Vector3d ParseOffsets(const std::string& text) {
  Eigen::Vector3d v;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf", &v(0), &v(1), &v(2)) != 3)
    throw accelcal::Error("OFFSETS must be x,y,z in counts, got '" + text + "'");
  return v;
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
  s.sensor.model.bias_counts += ParseOffsets(offsets);
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
    // As the wizard keeps a record step: chunks of the step's chunk_s (record_stream.h).
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
  // Backdate: the store stamps the current time; the analysis groups records by day.
  detail::SqliteDb db(path, false);
  detail::SqliteStatement(db, "UPDATE session SET created_utc = ?, updated_utc = ? WHERE id = 1")
      .Bind(1, date + "T09:00:00.000Z").Bind(2, date + "T09:01:00.000Z").Run();
}

}  // namespace

int main(int argc, char** argv) {
  const bool noise = argc == 8 && std::strcmp(argv[2], "--noise") == 0;
  if (!noise && (argc < 2 || argc > 3 || (argc == 3 && std::strcmp(argv[2], "--no-result") != 0))) {
    std::fprintf(stderr,
                 "usage: accelcal_make_session OUT.db [--no-result]\n"
                 "       accelcal_make_session OUT.db --noise PROCEDURE.toml SERIAL DATE OFFSETS SEED\n");
    return 2;
  }
  try {
    if (noise) {
      MakeNoiseSession(argv[1], argv[3], argv[4], argv[5], argv[6], argv[7]);
    } else {
      MakeSession(argv[1], argc == 2);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accelcal_make_session: %s\n", e.what());
    return 1;
  }
  return 0;
}

// accelcal_make_session: writes a finished session for the end-to-end tests (until the wizard
// makes them): the 18 simulated captures of the default scenario, one per step, the device and
// operator inputs, and the calibration from fitting them.
//
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

#include "accelcal/error.h"
#include "accelcal/fit/calibration_fit.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/session/detail/sqlite_db.h"
#include "accelcal/session/session_store.h"
#include "accelcal/sim/scenario.h"
#include "accelcal/sim/virtual_bench.h"

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
      store->RecordResult(CalibrationToJson(MakeCalibration(summary, fit.gravity, captures, o.path)));
      store->MarkDone();
    }
  }
  if (!o.date_utc.empty()) {  // the store stamps "now"; a test needs other dates
    detail::SqliteDb db(o.path, false);
    detail::SqliteStatement(db, "UPDATE session SET created_utc = ?, updated_utc = ? WHERE id = 1")
        .Bind(1, o.date_utc).Bind(2, o.date_utc).Run();
  }
}

}  // namespace

int main(int argc, char** argv) {
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

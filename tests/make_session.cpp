// accelcal_make_session: writes a finished session for the end-to-end tests (until the wizard
// makes them): the 18 simulated captures of the default scenario, one per step, the device and
// operator inputs, and the calibration from fitting them.
//
//   accelcal_make_session OUT.db [--no-result]
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include <fmt/core.h>

#include "accelcal/error.h"
#include "accelcal/fit/calibration_fit.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/session/session_store.h"
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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3 || (argc == 3 && std::strcmp(argv[2], "--no-result") != 0)) {
    std::fprintf(stderr, "usage: accelcal_make_session OUT.db [--no-result]\n");
    return 2;
  }
  try {
    MakeSession(argv[1], argc == 2);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accelcal_make_session: %s\n", e.what());
    return 1;
  }
  return 0;
}

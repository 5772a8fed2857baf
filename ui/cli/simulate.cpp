#include "cli/simulate.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <iostream>
#include <memory>
#include <optional>

#include "accelcal/base/error.h"
#include "accelcal/io/atomic_write.h"
#include "accelcal/io/capture_set_writer.h"
#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/sim/virtual_bench.h"
#include "cli/commands.h"
#include "cli/shipped_files.h"
#include "accelcal/io/scenario_file.h"

namespace accelcal::cli {
namespace {

void WriteTruth(const std::string& path, const sim::Scenario& scenario) {
  WriteFileAtomically(path, sim::ScenarioTruthJsonText(scenario));
}

// Writes with `write` to the file at `path`, or to `stdout_stream` for "-".
template <typename WriteFn>
void WriteOutput(const std::string& path, std::ostream& stdout_stream, WriteFn&& write) {
  if (path == "-") {
    write(stdout_stream);
    stdout_stream.flush();
    return;
  }
  // Made in memory, then written at once (atomic_write.h): a full disk leaves no empty or
  // half-written file behind, and says so.
  std::ostringstream out;
  try {
    write(out);
  } catch (const Error& e) {
    throw Error("'" + path + "': " + e.what());
  }
  WriteFileAtomically(path, out.str());
}

// The recording, chunk by chunk as the bench makes it: a 12-hour record at 1 kHz never sits in
// memory whole. A file is still written atomically (PATH.tmp, renamed at the end).
void WriteRecordingStreamed(sim::VirtualBench& bench, const std::string& path,
                            std::ostream& stdout_stream) {
  std::optional<AtomicFileWriter> file;
  if (path != "-") file.emplace(path);
  std::ostringstream buffer;
  std::ostream& out = file ? buffer : stdout_stream;
  std::optional<RecordingWriter> writer;
  const auto pass_on = [&] {
    if (!file) return;
    file->Write(buffer.view());
    buffer.str({});
  };
  bench.SimulateRecording([&](const std::vector<Sample>& chunk) {
    if (!writer) writer.emplace(out, std::isfinite(chunk.front().temp_c));
    writer->Write(chunk);
    pass_on();
  });
  if (!writer) writer.emplace(out, false);
  writer->Flush();
  pass_on();
  if (file) file->Commit();
}

}  // namespace

void RunSimulate(const SimulateOptions& options, std::ostream& stdout_stream) {
  sim::Scenario scenario = sim::LoadScenario(options.scenario_path);
  if (options.seed) scenario.bench.seed = *options.seed;
  sim::VirtualBench bench(scenario);
  if (options.recording) {
    WriteRecordingStreamed(bench, options.output_path, stdout_stream);
  } else {
    CaptureSet set;
    set.source_name = options.scenario_path;
    set.captures = bench.SimulateCaptureSet();
    set.adc_range = scenario.adc.Range();
    WriteOutput(options.output_path, stdout_stream,
                [&](std::ostream& out) { WriteCaptureSet(out, set); });
  }
  if (!options.truth_path.empty()) WriteTruth(options.truth_path, scenario);
}

void SetupSimulateCommand(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* sub = app.add_subcommand(
      "simulate",
      "Run a virtual-bench scenario (a simulated accelerometer on a simulated bench: static\n"
      "poses and turntable runs; the shipped ones in share/accelcal/scenarios) and write the capture set it records,\n"
      "as `accelcal fit` reads it, or one continuous hand-turned recording of its static poses.");
  sub->footer(
      "Examples:\n"
      "  accelcal simulate bench_default -o captures.csv --truth truth.json\n"
      "  accelcal simulate bench_default.toml --seed 42 | head\n"
      "  accelcal simulate static_only.toml --recording -o recording.txt");
  sub->add_option("scenario", options->scenario_path, "Scenario file (TOML), or a shipped one's name")
      ->required()
      ->transform(ShippedFile(kShippedScenarios));
  sub->add_option("-o,--output", options->output_path,
                  "Output file; '-' or absent: standard output");
  sub->add_flag("--recording", options->recording,
                "Write one continuous recording (t ax ay az temp_c) of the static poses instead "
                "of a capture set");
  sub->add_option("--seed", options->seed, "Random seed, overriding the scenario's [bench] seed");
  sub->add_option("--truth", options->truth_path,
                  "Also write the true sensor parameters (JSON) to this file");
  sub->callback([options] { RunSimulate(*options, std::cout); });
}

}  // namespace accelcal::cli

// `accelcal record`: samples from a live source (the simulated bench, a serial port, a TCP
// sample server, standard input, a recording replayed) into a continuous recording file, with
// the source's status on stderr once a second.
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/core.h>

#include "accelcal/bags/bag_open.h"
#include "accelcal/base/error.h"
#include "accelcal/io/capture_set_writer.h"
#include "accelcal/io/text_file.h"
#include "accelcal/acquire/source/remote_bench.h"
#include "accelcal/acquire/source/source_spec.h"
#include "accelcal/acquire/source/sensor_set_spec.h"
#include "accelcal/base/sensor_columns.h"
#include "cli/cli_checks.h"
#include "cli/record_sensors.h"
#include "cli/commands.h"
#include "cli/sample_format_flags.h"
#include "cli/source_preflight.h"
#include "cli/shipped_files.h"
#include "accelcal/io/scenario_file.h"

namespace accelcal::cli {
namespace {

struct RecordCommandOptions {
  std::string source_spec = "sim";
  std::string output_path;      // recording; "-" = standard output
  double duration_s = 0.0;      // span of t to record, s; 0 = until the end or Ctrl-C
  double status_every_s = 1.0;  // status line period (wall clock), s
  bool quiet = false;
  SourceOptions source;
  std::string scenario_path;  // sim: the bench; empty = the built-in default
  SampleFormatFlags format;   // every source but sim
  std::string bench_listen;   // sim: serve the bench's controls at HOST:PORT (remote_bench.h)
  std::string vehicle_calibration = "undo";  // mavlink: undo | as-is
  int sensors = 0;  // several sensors at once (record_sensors.h); 0 or 1: one
};

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void OnSigint(int) { g_interrupted = 1; }

// Ctrl-C ends the recording cleanly while this lives; the previous handler comes back after.
class SigintGuard {
 public:
  SigintGuard() {
    struct sigaction action {};
    action.sa_handler = OnSigint;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_);
    g_interrupted = 0;
  }
  ~SigintGuard() { sigaction(SIGINT, &previous_, nullptr); }
  SigintGuard(const SigintGuard&) = delete;
  SigintGuard& operator=(const SigintGuard&) = delete;

 private:
  struct sigaction previous_ {};
};

std::string StatusLine(const SampleSource& source) {
  return fmt::format("accelcal record: {}: {}\n", source.Describe(), source.status().BriefReport());
}

// One line per event, as it happens, so none is lost between status lines.
void ReportEvents(const SampleSource& source, const ReadResult& r, bool quiet) {
  if (quiet) return;
  const SourceStatus& s = source.status();
  if (r.malformed > 0)
    fmt::print(stderr, "accelcal record: {} malformed line{} skipped; latest: {}\n", r.malformed,
               r.malformed == 1 ? "" : "s", s.last_malformed);
  if (r.gaps > 0)
    fmt::print(stderr, "accelcal record: gap in t: {:.6g} s -> {:.6g} s ({:.3g} s missing)\n",
               s.last_gap.t_before_s, s.last_gap.t_after_s, s.last_gap.missing_s);
  if (r.went_dead) fmt::print(stderr, "accelcal record: link dead: {}\n", s.link_error);
  else if (r.link_lost) fmt::print(stderr, "accelcal record: link lost: {}\n", s.link_error);
  if (r.reconnected) fmt::print(stderr, "accelcal record: link back up\n");
  if (r.notice) fmt::print(stderr, "accelcal record: {}\n", s.last_notice);
}

// Drops the samples at or beyond end_s; true when any was (the duration is reached).
bool TrimToEnd(std::vector<Sample>* samples, double end_s) {
  bool reached = false;
  while (!samples->empty() && samples->back().t_s >= end_s) {
    samples->pop_back();
    reached = true;
  }
  return reached;
}

// The output stream: stdout for "-", else the file (owned by `file`).
std::ostream& OpenOutput(const std::string& path, std::ofstream* file) {
  if (path == "-") return std::cout;
  file->open(path, std::ios::binary | std::ios::trunc);
  if (!*file) throw Error("cannot open '" + path + "' for writing");
  return *file;
}

// The file could not take what was written (a full disk): cut it back to its last whole line
// and stop with the reason, saying how much the file keeps.
[[noreturn]] void FailWrite(const RecordCommandOptions& o, std::ofstream* file, long received) {
  const int err = errno;
  if (o.output_path == "-") throw Error(fmt::format("cannot write the samples to standard output: {}", std::strerror(err)));
  file->close();
  TruncateToLastWholeLine(o.output_path);
  throw Error(fmt::format("cannot write '{}': {}; recording stopped after {} samples received (the file "
                          "keeps its whole lines only)",
                          o.output_path, std::strerror(err), received));
}

void RunRecord(const RecordCommandOptions& o) {
  SourceOptions source_options = o.source;
  source_options.format = o.format.Resolve();
  if (!source_options.format.unit.is_counts())
    throw Error("--unit: record writes the readings as the source gives them; declare the unit "
                "to the command that reads the recording (fit --recording, apply, allan)");
  // A ROS bag's readings are m/s^2 (sensor_msgs/Imu): written as they are (one count per m/s^2,
  // so the values are the bag's own), and the file says to read them with --unit m/s^2.
  const SourceSpec spec = ParseSourceSpec(o.source_spec);
  const bool from_bag = spec.kind == SourceKind::kFile && bags::DetectBag(spec.path).has_value();
  if (from_bag) {
    source_options.format.unit = ReadingUnit{ReadingUnit::Kind::kMps2, 1.0};
    source_options.format.unit_declared = true;
  }
  if (!o.scenario_path.empty()) source_options.scenario = sim::LoadScenario(o.scenario_path);
  // Several sensors (a plate of N boards, a scenario's [fixture], a line of 3N columns): one
  // recording each, beside -o's name.
  std::string columns_error;  // a malformed list is the one-sensor reader's to refuse
  if (o.sensors > 1 || (source_options.scenario && source_options.scenario->fixture) ||
      (!o.format.columns.empty() && SplitSensorColumns(o.format.columns, &columns_error).size() > 1)) {
    if (o.output_path == "-")
      throw Error("-o -: several sensors are written one recording each, beside -o's name; give a file "
                  "name (plate.txt gives plate.SERIAL.txt)");
    SensorSetRequest request;
    request.sensors = o.sensors;
    request.columns = o.format.columns;
    std::unique_ptr<SensorSetSource> set = OpenSensorSet(o.source_spec, source_options, request);
    PrepareVehicle(*set, o.vehicle_calibration, o.quiet ? nullptr : stderr, o.quiet ? nullptr : stderr);
    SigintGuard sigint;
    return RecordSensorSet(*set, o.output_path, o.duration_s, o.quiet, &g_interrupted);
  }
  std::unique_ptr<SampleSource> source = OpenSource(o.source_spec, source_options);
  if (!o.quiet) PrepareVehicle(*source, o.vehicle_calibration, stderr, stderr);
  else PrepareVehicle(*source, o.vehicle_calibration, nullptr, nullptr);
  SigintGuard sigint;
  std::ofstream file;
  std::ostream& out = OpenOutput(o.output_path, &file);
  std::unique_ptr<RemoteBenchServer> bench_server;
  if (!o.bench_listen.empty()) {
    bench_server = std::make_unique<RemoteBenchServer>(
        ParseHostPort(o.bench_listen, o.bench_listen, "--bench-listen HOST:PORT, e.g. 127.0.0.1:0", true),
        source->bench());
    // Its port first, alone on a line of stderr, for the peer that drives it.
    fmt::print(stderr, "accelcal record: bench controls at port {}\n", bench_server->port());
  }
  std::optional<RecordingWriter> writer;  // created with the first samples (temperature or not)
  std::vector<Sample> chunk;              // one Read's samples; written, then cleared
  double end_s = INFINITY;
  using Clock = std::chrono::steady_clock;
  const auto status_every = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(o.status_every_s));
  auto next_status = Clock::now() + status_every;
  constexpr double kReadTimeoutS = 0.1;
  std::string why_stopped = "interrupted";
  // The writer throws when the stream fails (a full disk): say why, and keep whole lines only.
  try {
    while (!g_interrupted) {
      if (bench_server) bench_server->Serve([&] {
          if (writer) writer->Flush();
          out.flush();
        });
      chunk.clear();
      const ReadResult r = source->Read(kReadTimeoutS, &chunk);
      ReportEvents(*source, r, o.quiet);
      if (!chunk.empty() && !writer) {
        if (from_bag)
          out << "# readings in m/s^2 (the bag's sensor_msgs/Imu linear_acceleration, as "
                 "recorded): read this file with --unit m/s^2\n";
        writer.emplace(out, std::isfinite(chunk.front().temp_c));
        if (o.duration_s > 0.0) end_s = chunk.front().t_s + o.duration_s;
      }
      const bool reached = TrimToEnd(&chunk, end_s);
      if (writer) writer->Write(chunk);
      // A pipe feeds a live peer (a test vehicle): each chunk goes at once, not once a second.
      if (writer && o.output_path == "-" && !chunk.empty()) writer->Flush();
      if (!out) throw Error("cannot write the recording");
      if (reached) {
        why_stopped = "duration reached";
        break;
      }
      if (source->status().link == LinkState::kEnded) {
        why_stopped = "end of input";
        break;
      }
      if (Clock::now() >= next_status) {
        // Flushing once a second bounds what an interruption (or kill -9) can lose.
        if (writer) writer->Flush();
        if (!out) throw Error("cannot write the recording");
        if (!o.quiet) fmt::print(stderr, "{}", StatusLine(*source));
        next_status = Clock::now() + status_every;
      }
    }
    if (!writer) writer.emplace(out, false);
    writer->Flush();
    if (file.is_open()) file.close();
    if (!out || (o.output_path != "-" && file.fail())) throw Error("cannot write the recording");
  } catch (const Error&) {
    if (!out || file.fail()) FailWrite(o, &file, writer ? writer->written() : 0);
    throw;
  }
  if (!o.quiet && !source->DescribeReading().empty())
    fmt::print(stderr, "accelcal record: read {}\n", source->DescribeReading());
  if (!o.quiet)
    fmt::print(stderr, "{}accelcal record: {}; {} samples written to {}\n", StatusLine(*source),
               why_stopped, writer->written(), o.output_path);
}

}  // namespace

void SetupRecordCommand(CLI::App& app) {
  auto opts = std::make_shared<RecordCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "record",
      "Record samples from a live source into a continuous recording (lines 't ax ay az\n"
      "[temp_c]', as 'accelcal fit --recording' reads it). The source's status (link, rate,\n"
      "samples, malformed lines, gaps in t) goes to stderr once a second. Stops after --duration\n"
      "seconds of samples, at the end of a file or of standard input, or on Ctrl-C (what was\n"
      "received is written, exit status 0).\n\n"
      "Sources (--source): sim (the virtual bench), file:PATH (a recording, or a ROS bag's IMU\n"
      "topic: --topic; written in m/s^2 as the bag holds them), serial:DEVICE@BAUD,\n"
      "tcp:HOST:PORT, mavlink:LINK[,imu=N,rate=HZ], iio:DEVICE[,...], - (standard input).\n"
      "Line protocol in docs/formats.md, 'Sample sources'.");
  sub->footer(
      "Examples:\n"
      "  accelcal record --source serial:/dev/ttyUSB0@115200 -o board.txt\n"
      "  accelcal record --source tcp:192.168.7.2:5000 --duration 600 -o board.txt\n"
      "  accelcal record --source sim --speed 50 --duration 120 -o sim.txt\n"
      "  accelcal record --source mavlink:serial:/dev/ttyACM0@115200,imu=0,rate=200 -o px.txt\n"
      "  accelcal record --source iio:adxl345,rate=100 --duration 60 -o board.txt\n"
      "  accelcal record --source sim --speed 0 --sensors 8 --duration 600 -o plate.txt\n"
      "  accelcal fit --recording board.txt -o cal.json");
  sub->add_option("--source", opts->source_spec, "Sample source spec")->capture_default_str();
  sub->add_option("-o,--output", opts->output_path, "Recording to write ('-': standard output)")
      ->required();
  sub->add_option("--duration", opts->duration_s,
                  "Seconds of samples (span of t) to record; 0: until the end or Ctrl-C")
      ->check(NonNegative())->capture_default_str();
  sub->add_option("--speed", opts->source.sim.speed,
                  "sim: simulated seconds per wall second (1 real time; 0 as fast as possible)")
      ->capture_default_str();
  sub->add_option("--scenario", opts->scenario_path,
                  "sim: scenario file (TOML), or a shipped one's name; default: the built-in bench_default")
      ->transform(ShippedFile(kShippedScenarios));
  sub->add_option("--seed", opts->source.seed, "sim: random seed, overriding the scenario's");
  sub->add_flag("--realtime", opts->source.realtime,
                "file: replay paced by t instead of as fast as possible");
  sub->add_option("--dead-after", opts->source.dead_after_s,
                  "Report the link dead after this long without a sample, s")
      ->capture_default_str();
  opts->format.Bind(*sub, "the source's lines (file:, serial:, tcp:, -)");
  sub->add_option("--vehicle-calibration", opts->vehicle_calibration,
                  "mavlink: the vehicle's own accelerometer calibration: undo (taken out of every "
                  "sample) or as-is")
      ->check(CLI::IsMember({"undo", "as-is"}))->capture_default_str();
  sub->add_option("--bench-listen", opts->bench_listen,
                  "sim: serve the virtual bench's controls at HOST:PORT (port 0: any free one, said "
                  "on stderr), so that a wizard reading the samples over another link can place "
                  "the sensor (wizard --bench-control)");
  sub->add_option("--sensors", opts->sensors,
                  "sim: a plate of N boards recorded at once, one recording each beside -o's name "
                  "(plate.txt: plate.SIM01.txt, ...; docs/fixtures.md); also a scenario's [fixture] "
                  "or --columns naming several sensors")
      ->check(CLI::Range(1, 64));
  sub->add_flag("-q,--quiet", opts->quiet, "Print nothing but errors");
  sub->callback([opts] { RunRecord(*opts); });
}

}  // namespace accelcal::cli

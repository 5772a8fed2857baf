#include "accelcal/io/capture_set_writer.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/compile.h>
#include <fmt/format.h>

#include "accelcal/base/error.h"
#include "accelcal/io/csv_fields.h"

namespace accelcal {
namespace {

// fmt's "{}" is the shortest text that reads back as the same double; 2048.0 prints "2048".
std::string Number(double value) { return fmt::format("{}", value); }

// Appends Number(value)'s text. Readings in counts are whole numbers: those print as the
// integer they are (fmt's shortest form of such a double, below 1e15 and but for -0),
// without the shortest-digits search.
// Both forms go straight into the buffer: fmt::format_int for the integer, and the "{}" format
// compiled (FMT_COMPILE: the same text, without parsing the format string at every value,
// which cost as much as the formatting).
void AppendNumber(double value, fmt::memory_buffer* out) {
  constexpr double kExactInteger = 1e15;
  const bool negative_zero = value == 0.0 && std::signbit(value);
  if (std::fabs(value) < kExactInteger && value == std::trunc(value) && !negative_zero) {
    const fmt::format_int text(static_cast<long long>(value));
    out->append(text.data(), text.data() + text.size());
    return;
  }
  char text[32];  // the longest shortest form of a double is 24 characters
  const auto end = fmt::format_to(text, FMT_COMPILE("{}"), value);
  out->append(text, end);
}

// Empty for NaN: the format's "unknown".
std::string OptionalCsvNumber(double value) {
  return std::isnan(value) ? std::string() : Number(value);
}

// The `up` column's text: a face ("+z") or three numbers.
std::string UpText(const Capture& c) {
  if (!c.requested_up || c.kind != CaptureKind::kStatic) return {};
  const Eigen::Vector3d& u = *c.requested_up;
  for (SensorAxis a : {SensorAxis::kPlusX, SensorAxis::kMinusX, SensorAxis::kPlusY,
                       SensorAxis::kMinusY, SensorAxis::kPlusZ, SensorAxis::kMinusZ})
    if ((u - SensorAxisVector(a)).norm() < 1e-9) return std::string(SensorAxisToString(a));
  return fmt::format("{} {} {}", u.x(), u.y(), u.z());
}

void WriteRow(std::ostream& out, const Capture& c, const std::string& label, const Sample& s) {
  const bool turntable = c.kind == CaptureKind::kTurntable;
  out << c.id << ',' << CaptureKindToString(c.kind) << ',' << Number(s.t_s) << ','
      << Number(s.raw_counts.x()) << ',' << Number(s.raw_counts.y()) << ','
      << Number(s.raw_counts.z()) << ',' << OptionalCsvNumber(s.temp_c) << ','
      << (turntable ? OptionalCsvNumber(c.radius_m) : "") << ','
      << (turntable ? OptionalCsvNumber(c.rpm) : "") << ',' << label << ','
      << (turntable && c.up_axis ? SensorAxisToString(*c.up_axis) : "");
}

}  // namespace

void WriteCaptureSet(std::ostream& out, const CaptureSet& set) {
  out << "# accelcal capture set\n";
  if (set.adc_range) {
    out << "# adc_range_counts = " << Number(set.adc_range->min_counts) << ','
        << Number(set.adc_range->max_counts) << '\n';
  }
  // The `up` column only when some capture knows its requested pose (older readers lack it).
  const bool with_up = std::any_of(set.captures.begin(), set.captures.end(),
                                   [](const Capture& c) { return c.requested_up.has_value(); });
  out << "capture,kind,t,ax,ay,az,temp_c,radius_m,rpm,label,up_axis" << (with_up ? ",up\n" : "\n");
  for (const Capture& c : set.captures) {
    // A line break would split a row: the format is one row per line.
    if (c.label.find_first_of("\r\n") != std::string::npos) {
      throw Error(fmt::format("capture {}: a label cannot hold a line break", c.id));
    }
    const std::string label = CsvQuote(c.label);
    const std::string up = with_up ? "," + UpText(c) + "\n" : "\n";
    for (const Sample& s : c.samples) {
      WriteRow(out, c, label, s);
      out << up;
    }
  }
  if (!out) throw Error("cannot write the capture set");
}

void WriteCaptureSetFile(const std::string& path, const CaptureSet& set) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw Error("cannot open '" + path + "' for writing");
  try {
    WriteCaptureSet(out, set);
  } catch (const Error& e) {
    throw Error("'" + path + "': " + e.what());
  }
  out.close();
  if (!out) throw Error("cannot write '" + path + "'");
}

RecordingWriter::RecordingWriter(std::ostream& out, bool with_temperature)
    : out_(out), with_temperature_(with_temperature) {
  out_ << "# accelcal recording: t in s, ax ay az in raw counts"
       << (with_temperature_ ? ", temp_c in degC" : "") << '\n';
  out_ << (with_temperature_ ? "# t ax ay az temp_c\n" : "# t ax ay az\n");
  if (!out_) throw Error("cannot write the recording");
}

void RecordingWriter::Write(const std::vector<Sample>& samples) {
  // The lines of a chunk are formatted into one buffer (as Number() formats each value) and
  // written at once: a stream insertion and a string per value cost six times the reading.
  fmt::memory_buffer lines;
  for (const Sample& s : samples) {
    AppendNumber(s.t_s, &lines);
    for (int axis = 0; axis < 3; ++axis) {
      lines.push_back(' ');
      AppendNumber(s.raw_counts[axis], &lines);
    }
    if (with_temperature_) {
      lines.push_back(' ');
      AppendNumber(s.temp_c, &lines);
    }
    lines.push_back('\n');
  }
  out_.write(lines.data(), static_cast<std::streamsize>(lines.size()));
  written_ += static_cast<long>(samples.size());
  if (!out_) throw Error("cannot write the recording");
}

void RecordingWriter::Flush() {
  out_.flush();
  if (!out_) throw Error("cannot write the recording");
}

void WriteRecording(std::ostream& out, const std::vector<Sample>& samples) {
  const bool has_temp = std::any_of(samples.begin(), samples.end(),
                                    [](const Sample& s) { return !std::isnan(s.temp_c); });
  RecordingWriter writer(out, has_temp);
  writer.Write(samples);
}

}  // namespace accelcal

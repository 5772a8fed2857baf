#include "accelcal/bags/imu_message.h"

#include <array>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "accelcal/bags/byte_reader.h"
#include "accelcal/base/text_scan.h"

namespace accelcal::bags {
namespace {

constexpr size_t kImuDoubles = 4 + 9 + 3 + 9 + 3 + 9;
constexpr size_t kAccelerationDouble = 4 + 9 + 3 + 9;  // linear_acceleration's first
constexpr char kAxisNames[3] = {'x', 'y', 'z'};

struct Field {
  std::string type;  // as written, "std_msgs/Header", "float64[9]"
  std::string name;
};

// A type without its package ("std_msgs/msg/Header" and "std_msgs/Header" -> "Header").
std::string_view BaseType(std::string_view type) {
  const size_t slash = type.rfind('/');
  return slash == std::string_view::npos ? type : type.substr(slash + 1);
}

// The fields of one message's definition text (.msg): comments, blank lines and constants
// (TYPE NAME=VALUE) left out; a default value after the name ignored.
std::vector<Field> MsgFields(std::string_view text) {
  std::vector<Field> fields;
  detail::LineReader lines(text);
  std::string_view line;
  while (lines.Next(&line)) {
    if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    line = detail::TrimBlanks(line);
    if (line.empty()) continue;
    const size_t gap = line.find_first_of(" \t");
    if (gap == std::string_view::npos) continue;
    const std::string_view type = line.substr(0, gap);
    std::string_view rest = detail::TrimBlanks(line.substr(gap));
    const size_t end = rest.find_first_of(" \t=");
    if (end != std::string_view::npos && rest.substr(end).find('=') != std::string_view::npos &&
        detail::TrimBlanks(rest.substr(end)).front() == '=')
      continue;  // a constant
    fields.push_back({std::string(type), std::string(rest.substr(0, end))});
  }
  return fields;
}

// The sections of a definition with its dependencies (MCAP's ros1msg / ros2msg, ROS 1's
// message_definition): the message's own first, then "MSG: pkg/Type" ones after lines of '='.
struct Sections {
  std::string_view top;
  std::vector<std::pair<std::string, std::string_view>> dependencies;  // base type, text
};

Sections SplitDefinition(std::string_view text) {
  Sections s;
  const char* section_start = text.data();
  std::string name;    // the section's base type; empty for the message's own
  bool in_top = true;
  bool want_name = false;  // after a line of '=': the next non-blank line names the section
  const auto close = [&](const char* end) {
    const std::string_view body(section_start, static_cast<size_t>(end - section_start));
    if (in_top) s.top = body;
    else s.dependencies.emplace_back(name, body);
  };
  detail::LineReader lines(text);
  std::string_view line;
  while (lines.Next(&line)) {
    const std::string_view t = detail::TrimBlanks(line);
    if (t.size() >= 3 && t.find_first_not_of('=') == std::string_view::npos) {
      close(line.data());
      in_top = false;
      want_name = true;
      name.clear();
      section_start = line.data() + line.size();
      continue;
    }
    if (want_name && !t.empty()) {
      want_name = false;
      if (t.rfind("MSG:", 0) == 0) name = std::string(BaseType(detail::TrimBlanks(t.substr(4))));
      section_start = line.data() + line.size();
    }
  }
  close(text.data() + text.size());
  return s;
}

// True when `type` (without its package) is `expected`, or one of its '|'-separated spellings.
bool TypeIs(std::string_view type, std::string_view expected) {
  const std::string_view base = BaseType(type);
  while (!expected.empty()) {
    const size_t bar = expected.find('|');
    if (base == expected.substr(0, bar)) return true;
    if (bar == std::string_view::npos) break;
    expected.remove_prefix(bar + 1);
  }
  return false;
}

// Empty when `fields` are `expected` (types compared without their package); else the first
// difference, in words.
std::string CompareFields(const std::vector<Field>& fields,
                          const std::vector<std::pair<std::string_view, std::string_view>>& expected,
                          std::string_view what) {
  for (size_t i = 0; i < expected.size(); ++i) {
    const std::string_view shown = expected[i].first.substr(0, expected[i].first.find('|'));
    if (i >= fields.size())
      return fmt::format("{} ends before its field '{} {}'", what, shown, expected[i].second);
    if (!TypeIs(fields[i].type, expected[i].first) || fields[i].name != expected[i].second)
      return fmt::format("{} has '{} {}' where '{} {}' belongs", what,
                         detail::PrintableExcerpt(fields[i].type, 40),
                         detail::PrintableExcerpt(fields[i].name, 40), shown, expected[i].second);
  }
  if (fields.size() > expected.size())
    return fmt::format("{} has a field '{} {}' after its last", what,
                       detail::PrintableExcerpt(fields[expected.size()].type, 40),
                       detail::PrintableExcerpt(fields[expected.size()].name, 40));
  return {};
}

std::string DefinitionMismatch(std::string_view text, ImuEncoding encoding) {
  const Sections s = SplitDefinition(text);
  std::string why = CompareFields(MsgFields(s.top),
                                  {{"Header", "header"},
                                   {"Quaternion", "orientation"},
                                   {"float64[9]", "orientation_covariance"},
                                   {"Vector3", "angular_velocity"},
                                   {"float64[9]", "angular_velocity_covariance"},
                                   {"Vector3", "linear_acceleration"},
                                   {"float64[9]", "linear_acceleration_covariance"}},
                                  "the definition");
  if (!why.empty()) return why;
  for (const auto& [type, body] : s.dependencies) {
    const std::vector<Field> fields = MsgFields(body);
    if (type == "Header") {
      why = encoding == ImuEncoding::kCdr
                ? CompareFields(fields, {{"Time|time", "stamp"}, {"string", "frame_id"}},
                                "its Header (ROS 2's: stamp, frame_id)")
                : CompareFields(fields, {{"uint32", "seq"}, {"time", "stamp"}, {"string", "frame_id"}},
                                "its Header (ROS 1's: seq, stamp, frame_id)");
    } else if (type == "Vector3") {
      why = CompareFields(fields, {{"float64", "x"}, {"float64", "y"}, {"float64", "z"}}, "its Vector3");
    } else if (type == "Quaternion") {
      why = CompareFields(fields, {{"float64", "x"}, {"float64", "y"}, {"float64", "z"}, {"float64", "w"}},
                          "its Quaternion");
    } else if (type == "Time" && encoding == ImuEncoding::kCdr) {
      why = CompareFields(fields, {{"int32", "sec"}, {"uint32", "nanosec"}}, "its Time");
    }
    if (!why.empty()) return why;
  }
  return {};
}

bool Finish(const uint8_t* acceleration, bool big_endian, ImuReading* out, std::string* why) {
  for (int i = 0; i < 3; ++i) {
    const double v = LoadDouble(acceleration + 8 * i, big_endian);
    if (!std::isfinite(v)) {
      *why = fmt::format("its linear_acceleration.{} is {}, not a finite number", kAxisNames[i], v);
      return false;
    }
    out->linear_acceleration[i] = v;
  }
  if (out->stamp_nsec >= 1000000000u) {
    *why = fmt::format("its header stamp has {} nanoseconds (at most 999999999)", out->stamp_nsec);
    return false;
  }
  return true;
}

bool DecodeCdr(const uint8_t* data, size_t size, ImuReading* out, std::string* why) {
  if (size < 4) {
    *why = fmt::format("{} bytes: shorter than CDR's encapsulation header", size);
    return false;
  }
  const uint8_t kind = data[1];
  if (data[0] != 0 || kind > 1) {
    *why = fmt::format("its CDR encapsulation is {:02x} {:02x}: only CDR (XCDR1, 00 00 and 00 01, what "
                       "ROS 2 writes) is read", data[0], data[1]);
    return false;
  }
  const bool big = kind == 0;
  const uint8_t* body = data + 4;
  const size_t n = size - 4;
  if (n < 12) {
    *why = fmt::format("{} bytes: too short for a sensor_msgs/msg/Imu", size);
    return false;
  }
  out->stamp_sec = big ? LoadBig<int32_t>(body) : LoadLittle<int32_t>(body);
  out->stamp_nsec = big ? LoadBig<uint32_t>(body + 4) : LoadLittle<uint32_t>(body + 4);
  const uint32_t id_length = big ? LoadBig<uint32_t>(body + 8) : LoadLittle<uint32_t>(body + 8);
  if (id_length > n - 12) {
    *why = fmt::format("{} bytes: its frame_id of {} bytes runs past its end", size, id_length);
    return false;
  }
  const size_t doubles_at = (12 + size_t{id_length} + 7) / 8 * 8;
  const size_t need = doubles_at + kImuDoubles * 8;
  // rmw may pad the message to a multiple of 4 bytes.
  if (n < need || n > need + 7) {
    *why = fmt::format("{} bytes, where a sensor_msgs/msg/Imu with this frame_id has {}", size, need + 4);
    return false;
  }
  return Finish(body + doubles_at + kAccelerationDouble * 8, big, out, why);
}

bool DecodeRos1(const uint8_t* data, size_t size, ImuReading* out, std::string* why) {
  if (size < 16) {
    *why = fmt::format("{} bytes: too short for a sensor_msgs/Imu", size);
    return false;
  }
  out->stamp_sec = LoadLittle<uint32_t>(data + 4);
  out->stamp_nsec = LoadLittle<uint32_t>(data + 8);
  const uint32_t id_length = LoadLittle<uint32_t>(data + 12);
  if (id_length > size - 16) {
    *why = fmt::format("{} bytes: its frame_id of {} bytes runs past its end", size, id_length);
    return false;
  }
  const size_t doubles_at = 16 + size_t{id_length};
  if (size != doubles_at + kImuDoubles * 8) {
    *why = fmt::format("{} bytes, where a sensor_msgs/Imu with this frame_id has {}", size,
                       doubles_at + kImuDoubles * 8);
    return false;
  }
  return Finish(data + doubles_at + kAccelerationDouble * 8, false, out, why);
}

}  // namespace

bool IsImuType(std::string_view type) {
  return type == "sensor_msgs/msg/Imu" || type == "sensor_msgs/Imu";
}

bool ImuEncodingOf(const BagConnection& connection, ImuEncoding* encoding, std::string* why) {
  if (connection.encoding == "cdr") {
    *encoding = ImuEncoding::kCdr;
    return true;
  }
  if (connection.encoding == "ros1") {
    *encoding = ImuEncoding::kRos1;
    return true;
  }
  *why = fmt::format("its messages are encoded as '{}': CDR (ROS 2) and ROS 1's serialization are read",
                     detail::PrintableExcerpt(connection.encoding, 40));
  return false;
}

std::string ImuSchemaMismatch(const BagConnection& connection, ImuEncoding encoding) {
  if (encoding == ImuEncoding::kRos1 && !connection.md5sum.empty() && connection.md5sum != "*" &&
      connection.md5sum != kRos1ImuMd5)
    return fmt::format("its md5sum is {}, not sensor_msgs/Imu's {}",
                       detail::PrintableExcerpt(connection.md5sum, 40), kRos1ImuMd5);
  if (connection.schema.empty()) return {};
  if (connection.schema_encoding == "ros2msg" || connection.schema_encoding == "ros1msg")
    return DefinitionMismatch(connection.schema, encoding);
  return {};  // ros2idl, or a definition in another language: the messages' sizes are checked
}

bool DecodeImu(ImuEncoding encoding, const uint8_t* data, size_t size, ImuReading* out,
               std::string* why) {
  return encoding == ImuEncoding::kCdr ? DecodeCdr(data, size, out, why)
                                       : DecodeRos1(data, size, out, why);
}

}  // namespace accelcal::bags

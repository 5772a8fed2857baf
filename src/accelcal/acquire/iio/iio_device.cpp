#include "accelcal/acquire/iio/iio_device.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accelcal/acquire/source/spec_options.h"
#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal {
namespace {

namespace fs = std::filesystem;

constexpr const char* kIioUsage = "iio:DEVICE[,root=DIR][,dev=FILE][,x=CH,y=CH,z=CH][,rate=HZ][,poll]";

bool Exists(const std::string& path) {
  std::error_code ec;
  return fs::exists(path, ec);
}

// "accel_x" -> "accel"; "voltage0" -> "voltage" (the type whose shared attributes apply).
std::string ChannelType(const std::string& channel) {
  std::string type = channel.substr(0, channel.find('_'));
  while (!type.empty() && std::isdigit(static_cast<unsigned char>(type.back()))) type.pop_back();
  return type;
}

double ReadNumber(const std::string& path) {
  std::string error;
  const std::optional<std::string> text = ReadAttribute(path, &error);
  double v = kNaN;
  if (text && detail::ParseDouble(detail::TrimBlanks(*text), &v)) return v;
  return kNaN;
}

// The per-channel attribute, else the shared one of the channel's type.
void ReadScaleAndOffset(const std::string& dir, IioChannel* c) {
  for (const char* what : {"scale", "offset"}) {
    for (const std::string& file : {fmt::format("{}/in_{}_{}", dir, c->name, what),
                                    fmt::format("{}/in_{}_{}", dir, ChannelType(c->name), what)}) {
      if (!Exists(file)) continue;
      const double v = ReadNumber(file);
      if (std::string(what) == "scale") {
        c->scale = v;
        c->scale_file = fs::path(file).filename();
      } else {
        c->offset_counts = v;
        c->offset_file = fs::path(file).filename();
      }
      break;
    }
  }
}

std::optional<IioScanElement> ReadScanElement(const std::string& scan_dir, const std::string& name,
                                              const std::string& label) {
  const std::string base = fmt::format("{}/in_{}", scan_dir, name);
  if (!Exists(base + "_en") || !Exists(base + "_type") || !Exists(base + "_index")) return std::nullopt;
  std::string error;
  const std::optional<std::string> type_text = ReadAttribute(base + "_type", &error);
  if (!type_text) throw Error(fmt::format("{}: {}", label, error));
  std::string why;
  const std::optional<IioScanType> type = ParseIioScanType(*type_text, &why);
  if (!type) throw Error(fmt::format("{}: in_{}_type: {}", label, name, why));
  const double index = ReadNumber(base + "_index");
  if (!(index >= 0.0)) throw Error(fmt::format("{}: in_{}_index is not an index", label, name));
  return IioScanElement{name, static_cast<int>(index), *type, 0};
}

// The device directory: by id ("iio:device0", "device0") or by the `name` attribute.
std::string FindDeviceDir(const IioSourceSpec& spec) {
  if (!Exists(spec.root))
    throw Error(fmt::format("iio:{}: {} does not exist: no IIO device on this machine (is the "
                            "driver loaded?)", spec.device, spec.root));
  const std::string id = spec.device.rfind("iio:", 0) == 0 ? spec.device
                         : spec.device.rfind("device", 0) == 0 ? "iio:" + spec.device
                                                               : "";
  std::vector<std::string> seen;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(spec.root, ec)) {
    const std::string dir_id = e.path().filename();
    if (dir_id.rfind("iio:device", 0) != 0 || !e.is_directory(ec)) continue;
    std::string error;
    const std::string name = ReadAttribute(e.path() / "name", &error).value_or("");
    seen.push_back(name.empty() ? dir_id : dir_id + " (" + name + ")");
    if (dir_id == id || (id.empty() && name == spec.device)) return e.path();
  }
  std::sort(seen.begin(), seen.end());
  throw Error(fmt::format("iio:{}: no such device in {}; {}", spec.device, spec.root,
                          seen.empty() ? "it has no IIO device"
                                       : fmt::format("it has {}", fmt::join(seen, ", "))));
}

}  // namespace

std::string IioSourceSpec::Describe() const {
  std::string text = "iio:" + device;
  if (root != "/sys/bus/iio/devices") text += ",root=" + root;
  if (!dev_file.empty()) text += ",dev=" + dev_file;
  if (channels != std::array<std::string, 3>{"accel_x", "accel_y", "accel_z"})
    text += fmt::format(",x={},y={},z={}", channels[0], channels[1], channels[2]);
  if (!std::isnan(rate_hz)) text += fmt::format(",rate={:g}", rate_hz);
  if (poll) text += ",poll";
  return text;
}

IioSourceSpec ParseIioSpec(const std::string& spec) {
  IioSourceSpec s;
  const SpecParts parts = SplitSpecOptions(spec.substr(4));
  s.device = parts.head;
  if (s.device.empty()) throw Error(fmt::format("source '{}': expected {}", spec, kIioUsage));
  for (const SpecOption& o : parts.options) {
    const std::string& value = o.value;
    if (o.key != "poll" && value.empty())
      throw Error(fmt::format("source '{}': {} needs a value ({}=...)", spec, o.key, o.key));
    if (o.key == "root") s.root = value;
    else if (o.key == "dev") s.dev_file = value;
    else if (o.key == "x") s.channels[0] = value;
    else if (o.key == "y") s.channels[1] = value;
    else if (o.key == "z") s.channels[2] = value;
    else if (o.key == "poll" && !o.has_value) s.poll = true;
    else if (o.key == "rate") {
      if (!detail::ParseDouble(value, &s.rate_hz) || !(s.rate_hz > 0.0) || s.rate_hz > 1e5)
        throw Error(fmt::format("source '{}': rate={} is not a rate in Hz (0 .. 100000)", spec, value));
    } else {
      throw Error(fmt::format("source '{}': unknown option '{}': expected {}", spec, o.text, kIioUsage));
    }
  }
  return s;
}

std::optional<std::string> ReadAttribute(const std::string& path, std::string* error) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    *error = fmt::format("{}: {}", fs::path(path).filename().string(), std::strerror(errno));
    return std::nullopt;
  }
  char buffer[256];
  const ssize_t n = ::read(fd, buffer, sizeof buffer);
  const int err = errno;
  ::close(fd);
  if (n < 0) {
    *error = fmt::format("{}: read: {}", fs::path(path).filename().string(), std::strerror(err));
    return std::nullopt;
  }
  std::string text(buffer, static_cast<size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

bool WriteAttribute(const std::string& path, const std::string& value, std::string* error) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_TRUNC);
  if (fd < 0) {
    *error = fmt::format("{}: {}", fs::path(path).filename().string(), std::strerror(errno));
    return false;
  }
  const std::string line = value + "\n";
  const ssize_t n = ::write(fd, line.data(), line.size());
  const int err = errno;
  ::close(fd);
  if (n != static_cast<ssize_t>(line.size())) {
    *error = fmt::format("{}: write '{}': {}", fs::path(path).filename().string(), value,
                         n < 0 ? std::strerror(err) : "cut short");
    return false;
  }
  return true;
}

IioDevice FindIioDevice(const IioSourceSpec& spec) {
  IioDevice d;
  d.dir = FindDeviceDir(spec);
  d.id = fs::path(d.dir).filename();
  std::string error;
  d.name = ReadAttribute(d.dir + "/name", &error).value_or("");
  d.dev_file = spec.dev_file.empty() ? "/dev/" + d.id : spec.dev_file;
  // The 5.11+ layout keeps the scan elements in buffer0/; older kernels in scan_elements/.
  if (Exists(d.dir + "/buffer0/enable")) {
    d.buffer_dir = d.dir + "/buffer0";
    d.scan_dir = Exists(d.dir + "/buffer0/in_timestamp_en") || !Exists(d.dir + "/scan_elements")
                     ? d.buffer_dir : d.dir + "/scan_elements";
  } else if (Exists(d.dir + "/buffer/enable")) {
    d.buffer_dir = d.dir + "/buffer";
    d.scan_dir = d.dir + "/scan_elements";
  }
  for (size_t j = 0; j < 3; ++j) {
    IioChannel& c = d.axes[j];
    c.name = spec.channels[j];
    const std::string raw = fmt::format("{}/in_{}_raw", d.dir, c.name);
    if (Exists(raw)) c.raw_path = raw;
    ReadScaleAndOffset(d.dir, &c);
    if (!d.scan_dir.empty()) c.scan = ReadScanElement(d.scan_dir, c.name, d.Label());
    if (c.raw_path.empty() && !c.scan)
      throw Error(fmt::format("{}: no channel '{}' (neither in_{}_raw nor a scan element in_{}_en): "
                              "name the channels with x=,y=,z= (e.g. x=voltage0,y=voltage1,z=voltage2)",
                              d.Label(), c.name, c.name, c.name));
  }
  if (!d.scan_dir.empty()) d.timestamp = ReadScanElement(d.scan_dir, "timestamp", d.Label());
  if (Exists(d.dir + "/sampling_frequency")) d.sampling_frequency_path = d.dir + "/sampling_frequency";
  if (Exists(d.dir + "/trigger/current_trigger")) {
    d.has_trigger_file = true;
    d.trigger = ReadAttribute(d.dir + "/trigger/current_trigger", &error).value_or("");
  }
  return d;
}

int LayOutRecord(IioDevice* device) {
  std::vector<IioScanElement*> elements;
  for (IioChannel& c : device->axes)
    if (c.scan) elements.push_back(&*c.scan);
  if (device->timestamp) elements.push_back(&*device->timestamp);
  std::sort(elements.begin(), elements.end(),
            [](const IioScanElement* a, const IioScanElement* b) { return a->index < b->index; });
  int bytes = 0, largest = 1;
  for (IioScanElement* e : elements) {
    const int length = e->type.ElementBytes();
    bytes = (bytes + length - 1) / length * length;
    e->offset = bytes;
    bytes += length;
    largest = std::max(largest, length);
  }
  return (bytes + largest - 1) / largest * largest;
}

std::vector<std::string> DescribeIioDevice(const IioDevice& d) {
  std::vector<std::string> lines;
  lines.push_back(fmt::format("device: {} at {}", d.Label(), d.dir));
  const char* axis = "xyz";
  for (size_t j = 0; j < 3; ++j) {
    const IioChannel& c = d.axes[j];
    std::string line = fmt::format("{}: in_{}", axis[j], c.name);
    if (c.scan) line += fmt::format(", scan element {} ({}, index {})", c.name, c.scan->type.Describe(), c.scan->index);
    line += std::isnan(c.scale) ? ", no scale attribute"
                                : fmt::format(", scale {:g} per count ({})", c.scale, c.scale_file);
    if (!std::isnan(c.offset_counts)) line += fmt::format(", offset {:g} counts ({})", c.offset_counts, c.offset_file);
    lines.push_back(line);
  }
  lines.push_back("readings are kept as raw counts: the scale and offset above are stated, not applied "
                  "(the calibration's bias and scale replace them)");
  if (d.timestamp) lines.push_back(fmt::format("timestamp: {} (index {}), ns", d.timestamp->type.Describe(), d.timestamp->index));
  if (!d.buffer_dir.empty())
    lines.push_back(fmt::format("buffer: {} (scan elements in {}), records read from {}",
                                fs::path(d.buffer_dir).filename().string(),
                                fs::path(d.scan_dir).filename().string(), d.dev_file));
  else
    lines.push_back("buffer: none (the *_raw files are polled)");
  if (d.has_trigger_file)
    lines.push_back(d.trigger.empty() ? "trigger: none set (trigger/current_trigger is empty)"
                                      : "trigger: " + d.trigger);
  if (!d.sampling_frequency_path.empty()) {
    std::string error;
    lines.push_back("sampling_frequency: " +
                    ReadAttribute(d.sampling_frequency_path, &error).value_or("unreadable (" + error + ")") + " Hz");
  }
  return lines;
}

}  // namespace accelcal

// A Linux IIO device as its sysfs directory shows it (Documentation/ABI/testing/sysfs-bus-iio):
//
//   /sys/bus/iio/devices/iio:deviceN/
//     name                          "adxl345", "TI-am335x-adc.0.auto", ...
//     in_accel_x_raw, in_voltage0_raw     one reading, in counts, read on demand
//     in_accel_scale | in_accel_x_scale   units per count (m/s^2 for accel, mV for voltage)
//     in_accel_offset | in_accel_x_offset counts added before scaling
//     sampling_frequency (+ _available)   Hz
//     trigger/current_trigger       the trigger that starts a buffered scan (may be empty)
//     buffer/{enable,length} + scan_elements/in_X_{en,index,type}     (older kernels)
//     buffer0/{enable,length,in_X_en,in_X_index,in_X_type}            (5.11+ layout)
//   /dev/iio:deviceN                the buffer's records, one per scan
//
// A record holds the enabled scan elements in index order, each aligned to its own size, the
// record padded to its largest element (the kernel's iio_compute_scan_bytes); the timestamp
// channel (in_timestamp, le:s64/64>>0, ns) is an element like the others.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "accelcal/acquire/iio/iio_scan_type.h"
#include "accelcal/base/capture.h"

namespace accelcal {

struct IioSourceSpec {
  std::string device;                        // "adxl345", "iio:device0"
  std::string root = "/sys/bus/iio/devices";
  std::string dev_file;                      // empty: /dev/<the device's id>
  std::array<std::string, 3> channels = {"accel_x", "accel_y", "accel_z"};
  double rate_hz = kNaN;                     // sampling_frequency to set, or the poll rate
  bool poll = false;                         // poll *_raw even when the device has a buffer

  // "iio:adxl345", with the options that differ from the defaults.
  std::string Describe() const;
};

// iio:DEVICE[,root=DIR][,dev=FILE][,x=CH,y=CH,z=CH][,rate=HZ][,poll]. Throws accelcal::Error
// naming the spec for anything malformed.
IioSourceSpec ParseIioSpec(const std::string& spec);

struct IioScanElement {
  std::string name;  // "accel_x", "timestamp"
  int index = -1;
  IioScanType type;
  int offset = 0;    // byte offset in a record, once laid out
};

struct IioChannel {
  std::string name;             // "accel_x", "voltage0"
  std::string raw_path;         // in_<name>_raw ("" when absent)
  double scale = kNaN;          // units per count, from in_<name>_scale or the shared in_<type>_scale
  double offset_counts = kNaN;  // from in_<name>_offset or in_<type>_offset
  std::string scale_file, offset_file;  // where they were read
  std::optional<IioScanElement> scan;
};

struct IioDevice {
  std::string dir;        // the sysfs directory
  std::string id;         // "iio:device0"
  std::string name;       // from `name`
  std::string dev_file;   // where records are read
  std::array<IioChannel, 3> axes;
  std::optional<IioScanElement> timestamp;
  std::string buffer_dir;  // ".../buffer0" or ".../buffer"; empty: no buffer
  std::string scan_dir;    // where the scan elements are
  std::string sampling_frequency_path;  // empty: none
  std::string trigger;     // trigger/current_trigger ("" when none or absent)
  bool has_trigger_file = false;

  // "iio:device0 (adxl345)".
  std::string Label() const { return name.empty() ? id : id + " (" + name + ")"; }
  bool buffered() const {
    return !buffer_dir.empty() && axes[0].scan && axes[1].scan && axes[2].scan;
  }
};

// Finds the device and reads what it offers. Throws accelcal::Error naming the root and listing
// what is there (no such device; a channel missing; a scan type not understood).
IioDevice FindIioDevice(const IioSourceSpec& spec);

// Lays out the record of the axes (and the timestamp when there is one): offsets set, bytes per
// record returned (the kernel's rule).
int LayOutRecord(IioDevice* device);

// A sysfs attribute's text without its trailing newline; nullopt with *error (the system's
// reason, naming the file) when it cannot be read.
std::optional<std::string> ReadAttribute(const std::string& path, std::string* error);
// Writes `value` to the attribute; false with *error.
bool WriteAttribute(const std::string& path, const std::string& value, std::string* error);

// The device's description for a person, one fact per line: channels and their scan types,
// scale and offset (stated, not applied), sampling frequency, trigger, buffer layout.
std::vector<std::string> DescribeIioDevice(const IioDevice& device);

}  // namespace accelcal

// The options after a device spec's first part, as mavlink: and iio: write them:
// "tcp:127.0.0.1:5760,imu=1,rate=200" -> the head "tcp:127.0.0.1:5760" and the options
// imu=1, rate=200 (a bare word such as "poll" has an empty value).
#pragma once

#include <string>
#include <vector>

namespace accelcal {

struct SpecOption {
  std::string key;
  std::string value;
  bool has_value = false;  // "key=value" (possibly empty) rather than a bare "key"
  std::string text;        // as written, for messages
};

struct SpecParts {
  std::string head;
  std::vector<SpecOption> options;
};

// Splits `body` at its commas.
SpecParts SplitSpecOptions(const std::string& body);

}  // namespace accelcal

// A set of captures as read from a capture-set file (or exported by a session), with the
// metadata that travels with it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/base/capture.h"

namespace accelcal {

// The ADC's output range, counts (inclusive). A reading at either end may be clipped.
struct AdcRange {
  double min_counts = 0.0;
  double max_counts = 0.0;
};

struct CaptureSet {
  std::string source_name;            // file name, for messages
  std::vector<Capture> captures;      // in file order
  std::optional<AdcRange> adc_range;  // from "# adc_range_counts = MIN,MAX", if present
};

}  // namespace accelcal

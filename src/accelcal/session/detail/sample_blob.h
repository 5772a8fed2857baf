// The raw samples of a capture as one BLOB in the store: per sample five IEEE-754 binary64
// values t_s, ax, ay, az (counts), temp_c (NaN when unknown), little-endian, back to back
// (40 bytes a sample). Compact, and bit-exact both ways (NaN payloads included).
#pragma once

#include <vector>

#include "accelcal/base/capture.h"

namespace accelcal::detail {

inline constexpr size_t kSampleBlobBytes = 5 * sizeof(double);

std::vector<unsigned char> EncodeSamples(const std::vector<Sample>& samples);
// Throws accelcal::Error when the size is not a whole number of samples.
std::vector<Sample> DecodeSamples(const std::vector<unsigned char>& blob);

}  // namespace accelcal::detail

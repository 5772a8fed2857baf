#include "accelcal/session/detail/sample_blob.h"

#include <bit>
#include <cstring>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::detail {

// The blob is little-endian; memcpy of host doubles is that only on little-endian hosts.
static_assert(std::endian::native == std::endian::little, "sample blobs assume a little-endian host");

std::vector<unsigned char> EncodeSamples(const std::vector<Sample>& samples) {
  std::vector<unsigned char> blob(samples.size() * kSampleBlobBytes);
  unsigned char* out = blob.data();
  for (const Sample& s : samples) {
    const double values[5] = {s.t_s, s.raw_counts.x(), s.raw_counts.y(), s.raw_counts.z(), s.temp_c};
    std::memcpy(out, values, kSampleBlobBytes);
    out += kSampleBlobBytes;
  }
  return blob;
}

std::vector<Sample> DecodeSamples(const std::vector<unsigned char>& blob) {
  if (blob.size() % kSampleBlobBytes != 0)
    throw Error(fmt::format("damaged sample blob: {} bytes is not a whole number of samples",
                            blob.size()));
  std::vector<Sample> samples(blob.size() / kSampleBlobBytes);
  const unsigned char* in = blob.data();
  for (Sample& s : samples) {
    double values[5];
    std::memcpy(values, in, kSampleBlobBytes);
    in += kSampleBlobBytes;
    s.t_s = values[0];
    s.raw_counts = Eigen::Vector3d(values[1], values[2], values[3]);
    s.temp_c = values[4];
  }
  return samples;
}

}  // namespace accelcal::detail

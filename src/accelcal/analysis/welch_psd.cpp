#include "accelcal/analysis/welch_psd.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::analysis {
namespace {

constexpr int kMinSegment = 16;
constexpr int kMinSegments = 8;

bool IsPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

// Periodic Hann window of length L (the DFT-even form used for spectral estimation; Harris,
// Proc. IEEE 66(1) 1978): w_n = 0.5 (1 - cos(2 pi n / L)).
std::vector<double> HannWindow(int length) {
  std::vector<double> w(static_cast<std::size_t>(length));
  for (int n = 0; n < length; ++n) w[static_cast<std::size_t>(n)] = 0.5 * (1.0 - std::cos(2.0 * M_PI * n / length));
  return w;
}

// The segment minus its least-squares line, times the window, into *out.
void DetrendAndWindow(const std::vector<double>& segment, const std::vector<double>& window,
                      std::vector<double>* out) {
  const long length = static_cast<long>(window.size());
  // Regress on centred index u = n - (L - 1) / 2, so slope and mean separate.
  const double centre = 0.5 * static_cast<double>(length - 1);
  double sum = 0.0, sum_uy = 0.0, sum_uu = 0.0;
  for (long n = 0; n < length; ++n) {
    const double u = static_cast<double>(n) - centre;
    const double y = segment[static_cast<std::size_t>(n)];
    sum += y;
    sum_uy += u * y;
    sum_uu += u * u;
  }
  const double mean = sum / static_cast<double>(length);
  const double slope = sum_uy / sum_uu;
  out->resize(static_cast<std::size_t>(length));
  for (long n = 0; n < length; ++n) {
    const double u = static_cast<double>(n) - centre;
    const std::size_t i = static_cast<std::size_t>(n);
    (*out)[i] = (segment[i] - mean - slope * u) * window[i];
  }
}

}  // namespace

std::string WelchOptions::Validate() const {
  if (segment_length != 0 && (!IsPowerOfTwo(segment_length) || segment_length < kMinSegment))
    return fmt::format("segment_length must be 0 (automatic) or a power of two >= {}, got {}",
                       kMinSegment, segment_length);
  if (!IsPowerOfTwo(max_segment_length) || max_segment_length < kMinSegment)
    return fmt::format("max_segment_length must be a power of two >= {}, got {}", kMinSegment,
                       max_segment_length);
  return "";
}

int ChooseSegmentLength(long n, const WelchOptions& options) {
  if (options.segment_length != 0) return n >= options.segment_length ? options.segment_length : 0;
  if (n < kMinSegment) return 0;
  // With 50 % overlap, L samples per segment give floor(2 n / L) - 1 segments.
  int length = kMinSegment;
  while (length * 2 <= options.max_segment_length && 2 * n / (length * 2) - 1 >= kMinSegments)
    length *= 2;
  return length;
}

int RequireSegmentLength(long n, const WelchOptions& options) {
  const int length = ChooseSegmentLength(n, options);
  if (length == 0) {
    throw Error(fmt::format("Welch PSD: {} samples are too few (at least {})", n,
                            std::max(kMinSegment, options.segment_length)));
  }
  return length;
}

WelchAccumulator::WelchAccumulator(int segment_length) {
  if (!IsPowerOfTwo(segment_length) || segment_length < kMinSegment)
    throw Error(fmt::format("Welch PSD: the segment length must be a power of two >= {}, got {}",
                            kMinSegment, segment_length));
  window_ = HannWindow(segment_length);
  for (double w : window_) window_power_ += w * w;
  segment_.reserve(static_cast<std::size_t>(segment_length));
  sum_power_.assign(static_cast<std::size_t>(segment_length / 2 + 1), 0.0);
}

void WelchAccumulator::Add(double x) {
  if (!std::isfinite(x))
    throw Error(fmt::format("Welch PSD: sample {} is not finite", num_values_));
  ++num_values_;
  segment_.push_back(x);
  if (segment_.size() == window_.size()) AddSegment();
}

// A full segment: its power into the sum, and its second half kept as the next segment's first
// (50 % overlap).
void WelchAccumulator::AddSegment() {
  DetrendAndWindow(segment_, window_, &windowed_);
  fft_.fwd(spectrum_, windowed_);
  for (std::size_t k = 0; k < sum_power_.size(); ++k) sum_power_[k] += std::norm(spectrum_[k]);
  ++num_segments_;
  const std::size_t half = window_.size() / 2;
  std::copy(segment_.begin() + static_cast<long>(half), segment_.end(), segment_.begin());
  segment_.resize(half);
}

PowerSpectrum WelchAccumulator::Finish(double rate_hz) const {
  if (!(rate_hz > 0.0) || !std::isfinite(rate_hz))
    throw Error(fmt::format("Welch PSD: the sample rate must be positive, got {}", rate_hz));
  const int length = static_cast<int>(window_.size());
  if (num_segments_ == 0)
    throw Error(fmt::format("Welch PSD: {} samples are too few (at least {})", num_values_, length));
  const int half = length / 2;
  PowerSpectrum out;
  out.segment_length = length;
  out.num_segments = num_segments_;
  out.resolution_hz = rate_hz / length;
  out.density = sum_power_;
  const double scale = 1.0 / (rate_hz * window_power_ * num_segments_);
  for (int k = 0; k <= half; ++k) {
    const double one_sided = (k == 0 || k == half) ? 1.0 : 2.0;
    out.density[static_cast<std::size_t>(k)] *= one_sided * scale;
    out.frequency_hz.push_back(k * out.resolution_hz);
  }
  return out;
}

PowerSpectrum WelchPsd(const std::vector<double>& x, double rate_hz, const WelchOptions& options) {
  if (std::string why = options.Validate(); !why.empty()) throw Error("Welch PSD: " + why);
  if (!(rate_hz > 0.0) || !std::isfinite(rate_hz))
    throw Error(fmt::format("Welch PSD: the sample rate must be positive, got {}", rate_hz));
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) throw Error(fmt::format("Welch PSD: sample {} is not finite", i));
  }
  WelchAccumulator welch(RequireSegmentLength(static_cast<long>(x.size()), options));
  for (double v : x) welch.Add(v);
  return welch.Finish(rate_hz);
}

}  // namespace accelcal::analysis

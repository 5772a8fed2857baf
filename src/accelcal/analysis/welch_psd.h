// Power spectral density by Welch's method (P. D. Welch, "The use of fast Fourier transform for
// the estimation of power spectra", IEEE Trans. Audio Electroacoust. 15(2), 1967): the record
// is cut into segments of L samples overlapping by 50 %, each segment has its least-squares
// straight line removed (mean and trend, so slow drift does not leak into the low bins) and is
// multiplied by a Hann window, and the squared magnitudes of the segments' DFTs are averaged.
//
// Scaling (one-sided, unit^2/Hz; G. Heinzel, A. Ruediger, R. Schilling, "Spectrum and spectral
// density estimation by the DFT", Max-Planck-Institut report, 2002, eq. 24):
//     P(f_k) = 2 |X_k|^2 / (fs sum_n w_n^2),  f_k = k fs / L,  k = 0 .. L/2,
// without the factor 2 at k = 0 and k = L/2. So white noise of std sigma sampled at fs has
// P = 2 sigma^2 / fs at every frequency, and the integral of P over 0..fs/2 is the variance
// (Parseval; exactly so for white noise, up to the window's leakage for a line).
//
// Units: `x` in any unit u, rate in Hz; the density in u^2/Hz.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include <unsupported/Eigen/FFT>

namespace accelcal::analysis {

struct WelchOptions {
  // Segment length L, samples: a power of two >= 16, or 0 to choose it from the record: the
  // largest power of two with at least 8 segments at 50 % overlap (L <= 2 n / 9), between 16
  // and max_segment_length.
  int segment_length = 0;
  int max_segment_length = 1 << 16;  // cap of the automatic choice, samples (power of two)

  // Empty when valid, else the problem.
  std::string Validate() const;
};

struct PowerSpectrum {
  std::vector<double> frequency_hz;  // k fs / L, k = 0 .. L/2
  std::vector<double> density;       // one-sided PSD, unit^2/Hz
  int segment_length = 0;            // L, samples
  int num_segments = 0;              // segments averaged
  double resolution_hz = 0.0;        // fs / L
};

// Welch's average built one value at a time, for a record read as it comes (noise_analysis.h):
// it holds one segment (L values), whatever the record's length. WelchPsd is this over a vector.
class WelchAccumulator {
 public:
  // segment_length: L, a power of two >= 16 (ChooseSegmentLength). Throws accelcal::Error
  // otherwise.
  explicit WelchAccumulator(int segment_length);
  // The next value; throws accelcal::Error when it is not finite.
  void Add(double x);
  // The PSD of the values added, sampled at rate_hz. Throws accelcal::Error when rate_hz is not
  // positive and finite or fewer than L values were added.
  PowerSpectrum Finish(double rate_hz) const;

 private:
  void AddSegment();

  std::vector<double> window_;   // Hann, L
  double window_power_ = 0.0;    // sum w_n^2
  std::vector<double> segment_;  // the values not yet past: at most L
  std::vector<double> sum_power_;  // sum over segments of |X_k|^2, k = 0 .. L/2
  int num_segments_ = 0;
  long num_values_ = 0;
  Eigen::FFT<double> fft_;
  std::vector<double> windowed_;  // scratch: the segment detrended and windowed
  std::vector<std::complex<double>> spectrum_;  // scratch
};

// The segment length WelchOptions would choose for n samples (0 when n < 16).
int ChooseSegmentLength(long n, const WelchOptions& options);
// The same, or throws accelcal::Error "Welch PSD: N samples are too few (at least L)" when the
// n samples hold no segment.
int RequireSegmentLength(long n, const WelchOptions& options);

// Welch PSD of `x` sampled at rate_hz. Throws accelcal::Error when the options are invalid,
// rate_hz is not positive and finite, a value is not finite, or the record is shorter than one
// segment (at least 16 samples).
PowerSpectrum WelchPsd(const std::vector<double>& x, double rate_hz,
                       const WelchOptions& options = {});

}  // namespace accelcal::analysis

// Screening captures before a fit: each capture that cannot be trusted gets a
// Capture::rejection_reason in words (empty = usable), so that reports can say why it was left
// out.
//
// Rules, checked on every capture (all that apply are reported, joined by "; "):
//
// 1. Too short: fewer than `min_samples` samples.
//      "12 samples, at least 20 needed"
// 2. Non-finite readings: any sample whose t or raw reading is NaN or infinite.
//      "3 samples are NaN or infinite (first at t = 1.23 s)"
// 3. Clipped: the ADC saturated on an axis, so the mean of that axis is biased toward the
//    middle. Only finite samples take part.
//    - ADC range known (`adc_range`): any reading at or beyond either limit is clipped.
//        "x clipped at the ADC limit 4095 counts in 57 of 1000 samples"
//    - ADC range unknown: a rail is inferred. An axis is clipped at its extreme value in the
//      capture (its maximum, or its minimum) when
//        a. at least `rail_fraction` (default 2%) of the capture's samples, and at least 2,
//           sit exactly at that extreme (a noisy reading rarely repeats its extreme that
//           often, a saturated one does), and
//        b. the extreme is a typical ADC rail for some width n in 8..32 bits: for a maximum
//           2^n - 1 (unsigned full scale) or 2^(n-1) - 1 (signed); for a minimum 0 (unsigned)
//           or -2^(n-1) (signed). A maximum of 0 or a minimum of 2^n - 1 is not a rail.
//        "z clipped at 32767 counts (a typical ADC rail; the range is not known) in 40 of
//         500 samples"
//      The inference can miss a rail that is not a power of two, and could flag a noise-free
//      signal that happens to sit at 0 counts: give the range when it is known.
// 4. Implausible turntable conditions: a turntable capture whose stated radius or speed no bench
//    turntable has (turntable_plausibility.h, the wizard's own bounds), e.g. a radius typed in
//    mm as m, or radius and speed swapped.
//      "stated radius 120 m is not a plausible turntable radius (expected 5 mm to 2 m) and speed
//       0.1 rpm is not a plausible turntable speed (expected 1 to 3000 rpm): are the radius and
//       the speed swapped?"
//
// Screening overwrites rejection_reason on every capture it is given.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "accelcal/base/capture_set.h"

namespace accelcal {

struct ScreeningOptions {
  // Fewest samples a capture needs, count. At least 2 (a covariance needs two).
  int min_samples = 20;
  // The ADC's output range, counts; nullopt when unknown (then rails are inferred).
  // Typically CaptureSet::adc_range.
  std::optional<AdcRange> adc_range;
  // When the range is unknown: the fraction of a capture's samples (0..1] that must sit at an
  // axis' extreme for that extreme to count as a rail.
  double rail_fraction = 0.02;

  // Empty when the options are usable; otherwise what is wrong with them.
  std::string Validate() const;
};

// Sets rejection_reason on each capture per the rules above.
// Throws accelcal::Error when options.Validate() fails.
void ScreenCaptures(std::vector<Capture>& captures, const ScreeningOptions& options);

// The rejection reason ScreenCaptures would give `capture` (empty when usable). Does not
// validate the options.
std::string ScreeningReason(const Capture& capture, const ScreeningOptions& options);

}  // namespace accelcal

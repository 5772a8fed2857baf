// Helpers shared by the unit tests.
#pragma once

#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"

namespace accelcal::testing {

// Runs `fn`, which must throw an InputError, and returns it; records a test failure (and
// returns an empty error) when it does not. `input` is shown in the failure message.
template <typename Fn>
InputError ExpectInputError(Fn&& fn, const std::string& input) {
  try {
    fn();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << input;
  return InputError("", 0, 0, "");
}

// The same double, bit for bit (the sign of zero, a NaN's payload).
inline bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace accelcal::testing

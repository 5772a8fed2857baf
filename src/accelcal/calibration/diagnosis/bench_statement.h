// What the technician is told of an adopted effect: one plain sentence whose size is a typed
// quantity in the bench's units (mm, %, counts at 1 g, deg), stated by the effect
// (Effect::InBenchTerms) and rendered by the front ends' words (app/wizard/diagnosis_words.h):
//
//   <lead><size><tail>          "the turntable radius seems " "3.0 mm longer" " than entered"
//                               " (+-0.2 mm)"
//
// The numbers stay numbers here: how many digits they deserve is the effect's to say, how they
// are written the renderer's.
#pragma once

#include <string>
#include <vector>

#include "accelcal/base/capture.h"

namespace accelcal {

struct BenchQuantity {
  enum class Shape {
    kNone,       // no size: "<lead><tail>"
    kValue,      // one value as it is: "1.9 mm/s^2"
    kDirection,  // one value by its size and direction, its 1-sigma after the tail:
                 // "3.0 mm longer" ... " (+-0.2 mm)"
    kPerAxis,    // one signed value per axis x, y, z: "x +4.0, y -2.0, z +0.0 mm"
  };
  Shape shape = Shape::kNone;
  std::vector<double> values;  // in `unit`
  double sigma = kNaN;         // kDirection: the value's 1-sigma, in `unit`
  std::string unit;            // "mm", "%", "counts per degC"
  int decimals = 1;            // digits after the point the bench can use
  std::string positive;        // kDirection: the direction of a value >= 0 ("longer")
  std::string negative;        // and of a negative one ("shorter")
};

struct BenchStatement {
  std::string lead;  // lower case, no final period
  BenchQuantity size;
  std::string tail;
};

}  // namespace accelcal

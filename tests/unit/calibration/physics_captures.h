// Capture sets from the independent physics bench (tests/physics/physics_bench.h: the standard
// library and Eigen only, written from the physics), as the project's captures: the generator of
// the effects the virtual bench does not have (a cubic response, cross-axis coupling, and the
// effects outside the library).
#pragma once

#include <random>
#include <string>
#include <vector>

#include "accelcal/base/capture.h"
#include "physics_bench.h"

namespace accelcal::testing {

struct PhysicsSet {
  physgen::CaptureSetData data;   // the truth: sensor, effects, references
  std::vector<Capture> captures;  // as the program reads them (ids 1..n)
};

// The bench of evaluate.sh: a drawn sensor, the seed plan (or the rich one), 10 s captures
// (turntable runs `turntable_s`), a warm-up 22 -> 28 degC.
inline PhysicsSet MakePhysicsSet(const physgen::Effects& effects, unsigned long long seed,
                                 bool rich = false, double turntable_s = 10.0) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + 12345);  // as accelcal_physgen generate
  const physgen::Sensor sensor = physgen::DrawSensor(physgen::Sensor{}, rng);
  const std::vector<physgen::CaptureSpec> plan =
      rich ? physgen::RichPlan(10.0, turntable_s) : physgen::SeedPlan(10.0, turntable_s);
  PhysicsSet set;
  set.data = physgen::Generate(sensor, effects, physgen::Bench{}, plan, rng);
  int id = 0;
  for (const physgen::CaptureData& c : set.data.captures) {
    Capture cap;
    cap.id = ++id;
    cap.label = c.spec.label;
    if (c.spec.kind == physgen::Kind::kTurntable) {
      cap.kind = CaptureKind::kTurntable;
      cap.radius_m = c.spec.radius_m;
      cap.rpm = c.spec.rpm;
      cap.up_axis = StringToSensorAxis(c.spec.up_axis);
    }
    for (const physgen::Sample& s : c.samples) cap.samples.push_back({s.t_s, s.raw_counts, s.temp_c});
    set.captures.push_back(std::move(cap));
  }
  return set;
}

}  // namespace accelcal::testing

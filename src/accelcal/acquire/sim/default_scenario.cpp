// DefaultScenario(): the code twin of scenarios/bench_default.toml (a test keeps them equal).
#include <fmt/core.h>

#include "accelcal/acquire/sim/scenario.h"

namespace accelcal::sim {
namespace {

CapturePlan StaticPose(const std::string& label, const Eigen::Vector3d& up) {
  CapturePlan c;
  c.kind = CaptureKind::kStatic;
  c.label = label;
  c.up = up.normalized();
  return c;
}

CapturePlan Turntable(SensorAxis radial, SensorAxis up, double radius_m) {
  CapturePlan c;
  c.kind = CaptureKind::kTurntable;
  c.label = fmt::format("{} radial, {} up, r = {:.2f} m", SensorAxisToString(radial),
                        SensorAxisToString(up), radius_m);
  c.radius_m = radius_m;
  c.rpm = 120.0;
  c.radial_axis = radial;
  c.up_axis = up;
  return c;
}

}  // namespace

Scenario DefaultScenario() {
  Scenario s;
  s.source_name = "<default>";
  // MMA7260Q-like at +-6 g on a 12-bit unsigned ADC: 2048 counts per 6 g is ~34.8 counts/(m/s^2).
  s.sensor.model.bias_counts = {2051.3, 2039.6, 2062.8};
  s.sensor.model.scale_counts_per_mps2 = {34.62, 35.07, 34.41};
  s.sensor.model.a_yz_rad = 0.0042;
  s.sensor.model.a_zy_rad = -0.0031;
  s.sensor.model.a_zx_rad = 0.0057;
  s.sensor.noise_counts = {1.5, 1.5, 1.7};
  s.sensor.rate_hz = 100.0;
  s.adc.bits = 12;
  s.adc.is_signed = false;
  s.bench.seed = 7;
  s.captures = {
      StaticPose("z up", {0, 0, 1}),           StaticPose("z down", {0, 0, -1}),
      StaticPose("x up", {1, 0, 0}),           StaticPose("x down", {-1, 0, 0}),
      StaticPose("y up", {0, 1, 0}),           StaticPose("y down", {0, -1, 0}),
      StaticPose("tilted +x+y+z", {1, 1, 1}),  StaticPose("tilted +x+y-z", {1, 1, -1}),
      StaticPose("tilted +x-y+z", {1, -1, 1}),
  };
  const SensorAxis mountings[3][2] = {{SensorAxis::kPlusX, SensorAxis::kPlusZ},
                                      {SensorAxis::kPlusY, SensorAxis::kPlusZ},
                                      {SensorAxis::kPlusZ, SensorAxis::kPlusX}};
  for (const auto& m : mountings) {
    for (double radius_m : {0.05, 0.10, 0.15})
      s.captures.push_back(Turntable(m[0], m[1], radius_m));
  }
  return s;
}

}  // namespace accelcal::sim

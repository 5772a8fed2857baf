#include "accelcal/acquire/sim/scenario.h"

#include <array>
#include <cmath>

#include <fmt/core.h>

namespace accelcal::sim {
namespace {


bool AllFinite(const Eigen::Vector3d& v) { return v.allFinite(); }

std::string ValidateSensor(const SensorSpec& s) {
  if (std::string why = s.model.Validate(); !why.empty()) return "sensor: " + why;
  if (!AllFinite(s.noise_counts) || (s.noise_counts.array() < 0.0).any()) {
    return "sensor.noise_counts must be finite and not negative";
  }
  if (!(s.rate_hz > 0.0) || !std::isfinite(s.rate_hz)) return "sensor.rate_hz must be positive";
  if (std::string why = s.bias_noise.Validate(); !why.empty()) return "sensor: " + why;
  return {};
}

std::string ValidateBench(const BenchSpec& b) {
  if (!(b.gravity_mps2 > 0.0) || !std::isfinite(b.gravity_mps2)) {
    return "bench.gravity_mps2 must be positive";
  }
  if (!(b.placement_error_deg >= 0.0)) return "bench.placement_error_deg must not be negative";
  if (!(b.gap_s >= 0.0)) return "bench.gap_s must not be negative";
  if (!(b.capture_duration_s > 0.0)) return "bench.capture_duration_s must be positive";
  if (!std::isfinite(b.temperature_c)) return "bench.temperature_c must be finite";
  if (!(b.recording_quiet_start_s >= 0.0))
    return "bench.recording_quiet_start_s must not be negative";
  if (!(b.move_s > 0.0)) return "bench.move_s must be positive";
  return {};
}

std::string ValidateCapture(const CapturePlan& c, int i) {
  const std::string where = fmt::format("capture {} ('{}')", i, c.label);
  if (!(std::isnan(c.duration_s) || c.duration_s > 0.0))
    return where + ": duration_s must be positive";
  if (c.kind == CaptureKind::kStatic) {
    if (!c.up.allFinite() || !(c.up.norm() > 0.0)) return where + ": up must be a non-zero vector";
    return {};
  }
  if (!(c.radius_m >= 0.0) || !std::isfinite(c.radius_m))
    return where + ": radius_m must not be negative";
  if (!(c.rpm >= 0.0) || !std::isfinite(c.rpm)) return where + ": rpm must not be negative";
  if (std::abs(SensorAxisVector(c.radial_axis).dot(SensorAxisVector(c.up_axis))) > 0.5) {
    return where + ": radial_axis and up_axis must be perpendicular";
  }
  return {};
}

std::string ValidateMistake(const Mistake& m, int i) {
  const std::string where = fmt::format("technician.mistake {}", i);
  const bool turntable = m.asked_radial.has_value() || m.asked_up_axis.has_value();
  if (m.static_request() == turntable)
    return where + ": ask either asked_up (a static pose) or asked_radial and asked_up_axis "
                   "(a turntable mounting)";
  if (turntable && !(m.asked_radial && m.asked_up_axis))
    return where + ": a turntable request needs both asked_radial and asked_up_axis";
  if (m.times < 1 || m.after < 0) return where + ": times must be >= 1 and after >= 0";
  if (m.static_request() && (m.radial || m.up_axis || !std::isnan(m.radius_m)))
    return where + ": a static pose can only be replaced by another `up`";
  if (turntable && m.up) return where + ": a turntable mounting is replaced by radial/up_axis/radius_m";
  if (m.radial.has_value() != m.up_axis.has_value())
    return where + ": a wrong mounting gives both radial and up_axis";
  if (m.radial && std::abs(SensorAxisVector(*m.radial).dot(SensorAxisVector(*m.up_axis))) > 0.5)
    return where + ": radial and up_axis must be perpendicular";
  if (!std::isnan(m.radius_m) && !(m.radius_m > 0.0)) return where + ": radius_m must be positive";
  if (!std::isnan(m.bump_at_s) && !(m.bump_at_s >= 0.0 && m.bump_duration_s > 0.0))
    return where + ": bump_at_s must not be negative and bump_duration_s must be positive";
  return {};
}

std::string ValidateTechnician(const Technician& t) {
  if (!(t.leveling_gain > 0.0 && t.leveling_gain <= 1.0))
    return "technician.leveling_gain must be in (0, 1]";
  for (const Shake& s : t.shakes)
    if (!(s.to_s > s.from_s) || !(s.rms_mps2 >= 0.0) || !std::isfinite(s.rms_mps2))
      return "technician.shake: to_s must exceed from_s and rms_mps2 must not be negative";
  for (int i = 0; i < static_cast<int>(t.mistakes.size()); ++i)
    if (std::string why = ValidateMistake(t.mistakes[static_cast<size_t>(i)], i); !why.empty()) return why;
  return {};
}

}  // namespace


double AdcSpec::MinCounts() const { return is_signed ? -std::ldexp(1.0, bits - 1) : 0.0; }

double AdcSpec::MaxCounts() const {
  return is_signed ? std::ldexp(1.0, bits - 1) - 1.0 : std::ldexp(1.0, bits) - 1.0;
}

double Scenario::CaptureDurationS(int index) const {
  const double d = captures.at(static_cast<std::size_t>(index)).duration_s;
  return std::isnan(d) ? bench.capture_duration_s : d;
}

std::string LabSpec::GravityAnswer(double bench_gravity_mps2) const {
  if (gravity != "measured") return gravity;
  return fmt::format("{:.5f} +- {:g}", bench_gravity_mps2, gravity_sigma_mps2);
}

double Scenario::SessionDurationS() const {
  double total = 0.0;
  for (int i = 0; i < static_cast<int>(captures.size()); ++i) {
    total += CaptureDurationS(i) + (i > 0 ? bench.gap_s : 0.0);
  }
  return total;
}

std::string Scenario::Validate() const {
  if (std::string why = ValidateSensor(sensor); !why.empty()) return why;
  if (adc.bits < 1 || adc.bits > 32) return "adc.bits must be between 1 and 32";
  if (std::string why = ValidateBench(bench); !why.empty()) return why;
  if (captures.empty()) return "the plan has no [[capture]]";
  for (int i = 0; i < static_cast<int>(captures.size()); ++i) {
    if (std::string why = ValidateCapture(captures[i], i); !why.empty()) return why;
  }
  for (const Bump& b : effects.bumps) {
    if (b.capture < 0 || b.capture >= static_cast<int>(captures.size())) {
      return fmt::format("effects.bump: capture {} is not in the plan (0..{})", b.capture,
                         captures.size() - 1);
    }
    if (!(b.duration_s > 0.0) || !(b.at_s >= 0.0)) {
      return "effects.bump: duration_s must be positive and at_s not negative";
    }
  }
  if (!(effects.rpm_scale > -1.0)) return "effects.rpm_scale must be greater than -1";
  if (!effects.settling_share.allFinite() || (effects.settling_share.array() < 0.0).any() ||
      (effects.settling_share.array() >= 1.0).any())
    return "effects.settling_share must be within 0 (included) and 1 on each axis";
  if (!(effects.settling_tau_s > 0.0) || !std::isfinite(effects.settling_tau_s))
    return "effects.settling_tau_s must be positive";
  if (!bench.table_tilt_deg.allFinite() || (bench.table_tilt_deg.array().abs() > 30.0).any())
    return "bench.table_tilt_deg must be within +-30 deg";
  if (fixture) {
    if (fixture->boards.empty()) return "fixture: no [[fixture.board]]";
    if (std::string why = fixture->Validate(); !why.empty()) return why;
  }
  return ValidateTechnician(technician);
}

}  // namespace accelcal::sim

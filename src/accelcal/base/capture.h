// A capture: a stretch of raw samples taken in one pose (static) or one turntable mounting,
// and the statistics the fit uses from it.
//
// Units: t in s (one clock for the whole session), raw in ADC counts, temperature in degC,
// radius in m, turntable speed in rpm (revolutions per minute, as typed on the bench).
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace accelcal {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

enum class CaptureKind { kStatic, kTurntable };

// "static" / "turntable" (the spelling of the capture-set file and the store).
std::string_view CaptureKindToString(CaptureKind kind);
// Inverse of CaptureKindToString; nullopt for anything else.
std::optional<CaptureKind> StringToCaptureKind(std::string_view text);

// A signed sensor axis: "+x", "-x", "+y", "-y", "+z", "-z".
enum class SensorAxis { kPlusX, kMinusX, kPlusY, kMinusY, kPlusZ, kMinusZ };

std::string_view SensorAxisToString(SensorAxis axis);
std::optional<SensorAxis> StringToSensorAxis(std::string_view text);
// Unit vector of `axis` in sensor (platform) coordinates.
Eigen::Vector3d SensorAxisVector(SensorAxis axis);
// The name of a face ("+z") when `up` is within 1e-6 of one; else "(x, y, z)".
std::string DescribeUp(const Eigen::Vector3d& up);

struct Sample {
  double t_s = 0.0;
  Eigen::Vector3d raw_counts = Eigen::Vector3d::Zero();
  double temp_c = kNaN;  // NaN when the source has no temperature
};

// A sample whose time and counts are all finite (a NaN temperature is allowed): the checks that
// judge samples skip the others.
inline bool IsFinite(const Sample& s) { return std::isfinite(s.t_s) && s.raw_counts.allFinite(); }

// Running statistics of a capture (Welford's algorithm: one pass, numerically stable).
struct CaptureStats {
  long n = 0;
  Eigen::Vector3d mean_counts = Eigen::Vector3d::Zero();
  // Co-moment of the raw samples, sum (x - mean)(x - mean)^T over the samples, counts^2 (Welford's
  // M2): the sample covariance is this over n - 1 (Covariance()).
  Eigen::Matrix3d comoment_counts2 = Eigen::Matrix3d::Zero();
  double t_first_s = kNaN;
  double t_last_s = kNaN;
  double mean_t_s = kNaN;
  double mean_temp_c = kNaN;  // NaN when no sample carries a temperature
  double min_temp_c = kNaN;
  double max_temp_c = kNaN;
  Eigen::Vector3d min_counts = Eigen::Vector3d::Constant(kNaN);
  Eigen::Vector3d max_counts = Eigen::Vector3d::Constant(kNaN);
  bool any_non_finite = false;  // a NaN or infinite reading was seen (it is not accumulated)

  void Add(const Sample& s);
  // Sample covariance (n - 1 in the denominator), counts^2; NaN below two samples.
  Eigen::Matrix3d Covariance() const;
  // Covariance of the mean, counts^2: Covariance() / n. Assumes uncorrelated samples (white noise).
  Eigen::Matrix3d MeanCovariance() const;
  Eigen::Vector3d StdCounts() const;

 private:
  long temp_n_ = 0;  // samples that carried a temperature
};

CaptureStats ComputeStats(const std::vector<Sample>& samples);

// A static capture's reading once settled, when it was still settling as it was taken
// (calibration/settling.h): the asymptote of its samples and that estimate's covariance, which
// the fit uses instead of the plain mean.
struct SettledReading {
  Eigen::Vector3d mean_counts = Eigen::Vector3d::Zero();
  Eigen::Matrix3d mean_cov_counts2 = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset_counts = Eigen::Vector3d::Zero();  // plain mean less the asymptote
};

struct Capture {
  int id = 0;
  CaptureKind kind = CaptureKind::kStatic;
  std::string label;
  double radius_m = kNaN;  // turntable only: distance from the spin axis to the sensor, m
  double rpm = kNaN;       // turntable only: table speed, revolutions per minute
  // Turntable only: the standard uncertainty of radius_m that is this run's own, independent of
  // every other run's, m; 0: none (the ruler's reading error, common to every run, is the
  // budget's). A board away from a fixture plate's reference point has one: the plate is set
  // down anew for each run, turned by its placement error (base/fixture.h,
  // SensorRadiusPerTurnM). Not stored with the capture: worked out from the session's fixture.
  double radius_own_u_m = 0.0;
  // Turntable only, when known: the sensor axis that pointed up (the others lie in the table's
  // plane). Needed only by effects that depend on the mounting (the size effect).
  std::optional<SensorAxis> up_axis;
  // Static only, when known: the up direction the procedure asked for, sensor frame, unit length
  // (a capture set's `up` column; `accelcal export` fills it from the procedure). The fit warns
  // when the measured direction disagrees (calibration/pose_check.h).
  std::optional<Eigen::Vector3d> requested_up;
  std::vector<Sample> samples;

  // When the capture was left out of the fit: why (set by screening); empty when usable.
  std::string rejection_reason;
  bool used() const { return rejection_reason.empty(); }
  // Set when the capture was still settling and its asymptote is used (calibration/settling.h).
  std::optional<SettledReading> settled;

  // The statistics of `samples`, computed once and carried with the capture: handed over by the
  // capture engine, which accumulates them as the samples arrive (set_stats), or computed on
  // first use. Samples are only ever appended, so a change in their number recomputes them.
  const CaptureStats& stats() const;
  // `stats` must be those of `samples` as they are now (the capture engine's running ones).
  void set_stats(const CaptureStats& stats);

 private:
  mutable CaptureStats stats_;
  mutable std::size_t stats_of_samples_ = static_cast<std::size_t>(-1);  // samples.size() at stats_
};

// Table speed in rad/s from rpm.
inline double RpmToRadPerS(double rpm) { return rpm * 2.0 * M_PI / 60.0; }

// Magnitude of the specific force the sensor feels in a capture, m/s^2:
// g for a static capture, sqrt(g^2 + (w^2 r)^2) for a turntable capture (level table).
double ReferenceMagnitudeMps2(CaptureKind kind, double gravity_mps2, double radius_m, double rpm);

}  // namespace accelcal

// The Allan deviation engine against Stable32's published values (../shared/data/allan-reference,
// see its README) and against closed forms and its own batch reference.
#include "accelcal/analysis/allan_deviation.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/error.h"

namespace accelcal {
namespace {

const std::string kDir = std::string(ACCELCAL_SHARED_DATA_DIR) + "/allan-reference/";

// One row of a Stable32 table: AF Tau # Alpha MinSigma Sigma MaxSigma.
struct S32Row {
  int64_t m = 0;
  double tau_s = 0;
  int64_t n = 0;
  int alpha = 0;
  double lo = 0, sigma = 0, hi = 0;
};

std::vector<S32Row> ReadStable32(const std::string& name) {
  std::ifstream in(kDir + name);
  std::vector<S32Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    S32Row r;
    if (s >> r.m >> r.tau_s >> r.n >> r.alpha >> r.lo >> r.sigma >> r.hi) rows.push_back(r);
  }
  return rows;
}

std::vector<double> ReadColumn(const std::string& name) {
  std::ifstream in(kDir + name);
  std::vector<double> v;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    v.push_back(std::stod(line));
  }
  return v;
}

// The OCXO readings (Hz) as fractional frequency about 10 MHz, as Stable32 was given them.
std::vector<double> OcxoFractional() {
  std::vector<double> y = ReadColumn("ocxo_frequency.txt");
  for (double& v : y) v = (v - 1.0e7) / 1.0e7;
  return y;
}

// PHASE.DAT's phase readings (tau0 = 1) as frequency: first differences / tau0.
std::vector<double> PhaseDatFrequency() {
  const std::vector<double> x = ReadColumn("PHASE.DAT");
  std::vector<double> y;
  for (size_t i = 1; i < x.size(); ++i) y.push_back(x[i] - x[i - 1]);
  return y;
}

bool HaveData() { return std::filesystem::exists(kDir + "oadev_octave.txt"); }

double Rel(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

std::vector<int64_t> Factors(const std::vector<S32Row>& rows) {
  std::vector<int64_t> m;
  for (const S32Row& r : rows) m.push_back(r.m);
  return m;
}

// Points where the engine and Stable32 differ, each listed with its reason in the test that uses
// it. A listed point must still differ (so the lists stay true), by less than 2e-4 for numbers.
struct Exceptions {
  std::set<int64_t> alpha;   // noise identified differently
  std::set<int64_t> sigma;   // sigma off by 1e-4 .. 2e-4
  std::set<int64_t> bounds;  // a bound off by 1e-4 .. 2e-4
};

void ExpectWithin1e4(double ours, double theirs, bool listed, const std::string& what) {
  if (listed) {
    EXPECT_GT(Rel(ours, theirs), 1e-4) << what << ": listed as differing, now matches";
    EXPECT_LT(Rel(ours, theirs), 2e-4) << what;
  } else {
    EXPECT_LT(Rel(ours, theirs), 1e-4) << what << " ours " << ours << " Stable32 " << theirs;
  }
}

// Compares a curve with Stable32's rows: count, sigma and bounds within 1e-4 relative, alpha
// equal. Where alpha differs (listed), the bounds are checked with Stable32's alpha instead
// (they depend on alpha through the EDF only). `alpha_for_bounds` overrides the alpha (tables
// made with a fixed noise type).
void ExpectMatches(const AllanCurve& curve, const std::vector<S32Row>& rows, int64_t phase_points,
                   const Exceptions& ex, const std::string& what,
                   std::optional<int> alpha_for_bounds = std::nullopt) {
  ASSERT_EQ(curve.points.size(), rows.size()) << what;
  for (size_t i = 0; i < rows.size(); ++i) {
    const AllanPoint& p = curve.points[i];
    const S32Row& r = rows[i];
    const std::string at = what + " m=" + std::to_string(r.m);
    ASSERT_EQ(p.m, r.m) << what;
    EXPECT_EQ(p.num_terms, r.n) << at;
    ExpectWithin1e4(p.adev, r.sigma, ex.sigma.count(r.m) != 0, at + " sigma");
    if (!alpha_for_bounds) {
      if (ex.alpha.count(r.m) == 0) {
        EXPECT_EQ(p.alpha, r.alpha) << at;
      } else {
        EXPECT_NE(p.alpha, r.alpha) << at << ": listed as differing, now matches";
      }
    }
    if (r.lo > 0) {
      const int alpha = alpha_for_bounds ? *alpha_for_bounds : r.alpha;
      const double edf = AllanEdf(alpha, p.m, p.stride, phase_points);
      if (alpha == p.alpha) {
        EXPECT_DOUBLE_EQ(edf, p.edf) << at;
      }
      const DeviationBounds b =
          ChiSquareDeviationBounds(p.adev, edf, kOneSigmaConfidence, ChiSquareMethod::kStable32);
      const bool listed = ex.bounds.count(r.m) != 0;
      if (ex.sigma.count(r.m) != 0) {  // sigma itself differs: compare bounds / sigma
        ExpectWithin1e4(b.lo / p.adev, r.lo / r.sigma, false, at + " lo/sigma");
        ExpectWithin1e4(b.hi / p.adev, r.hi / r.sigma, listed, at + " hi/sigma");
      } else {
        ExpectWithin1e4(b.lo, r.lo, false, at + " lo");
        ExpectWithin1e4(b.hi, r.hi, listed, at + " hi");
      }
    }
  }
}

AllanCurve Batch(const std::vector<double>& y, const std::vector<S32Row>& rows,
                 AllanEstimator estimator) {
  return AllanAtFactors(y, 1.0, Factors(rows), estimator, kOneSigmaConfidence,
                        ChiSquareMethod::kStable32);
}

// The points of the all-tau table whose alpha the B1 ratio (fewer than 30 averages) does not
// reproduce: Stable32 reports white FM (0) where the B1 ratio with the normalisations of
// allan_confidence.h gives flicker FM (-1). Each variant tried (sample or population variance,
// overlapping or series Allan variance, N or N/m, geometric or arithmetic boundaries) failed
// more points; Stable32's source is not public.
const Exceptions kAllTauExceptions = {
    {1920, 1957, 1994, 2032, 2071, 2111, 2151, 2192, 2234, 2277, 2320, 2364, 2409}, {}, {}};

// The all-tau table (273 factors 1 .. 4929): sigma and count at every factor, alpha at all 167
// lag-1 points and at 93 of the 106 B1 points.
TEST(AllanStable32, OcxoOverlappingAllTau) {
  if (!HaveData()) GTEST_SKIP() << "no " << kDir << " (shared reference data absent)";
  const std::vector<S32Row> rows = ReadStable32("stable32_oadev_alltau.txt");
  ASSERT_EQ(rows.size(), 273u);
  ExpectMatches(Batch(OcxoFractional(), rows, AllanEstimator::kOverlapping), rows, 19983,
                kAllTauExceptions, "all-tau batch");
}

// The same through the streaming accumulator (every factor here is below full_overlap_max_m,
// so exact): its grid has other factors, compare those it shares with the table.
TEST(AllanStable32, OcxoOverlappingAllTauStreamed) {
  if (!HaveData()) GTEST_SKIP() << "no " << kDir << " (shared reference data absent)";
  const std::vector<S32Row> rows = ReadStable32("stable32_oadev_alltau.txt");
  AllanOptions options;
  options.tau0_s = 1.0;
  options.chi_square = ChiSquareMethod::kStable32;
  const AllanCurve curve = OverlappingAllan(OcxoFractional(), options);
  std::map<int64_t, AllanPoint> by_m;
  for (const AllanPoint& p : curve.points) by_m[p.m] = p;
  AllanCurve shared;
  std::vector<S32Row> shared_rows;
  for (const S32Row& r : rows) {
    if (by_m.count(r.m) != 0) {
      shared.points.push_back(by_m[r.m]);
      shared_rows.push_back(r);
    }
  }
  EXPECT_GE(shared_rows.size(), 20u);
  EXPECT_EQ(curve.points.back().m, 4096);  // the grid's last factor <= N/4 = 4995
  ExpectMatches(shared, shared_rows, 19983, kAllTauExceptions, "all-tau streamed");
}

// oadev_octave.txt's sigmas were not computed from this ocxo_frequency.txt: at AF = 1 the
// overlapping and non-overlapping Allan deviations are the same number, and the table reads
// 7.6143e-11 where adev_octave.txt and the all-tau table (same data) read 7.6106e-11 (allantools
// compares this table at 2e-3). So: sigmas within 2e-3; alpha equal where the lag-1 method
// applies (>= 30 averages; at 2048 and 4096 the B1 ratio of these data says -1 where Stable32's
// data gave 0); and the bounds as ratios to the table's own sigma, which depend only on alpha
// and the EDF, computed with the table's alpha, within 1e-4 (at 4096, edf 5.2, the upper one
// differs by 1.2e-4, as Stable32's iterative chi-square inverse does at small edf: see
// PhaseDatNonOverlapping).
TEST(AllanStable32, OcxoOverlappingOctave) {
  if (!HaveData()) GTEST_SKIP() << "no " << kDir << " (shared reference data absent)";
  const std::vector<S32Row> rows = ReadStable32("oadev_octave.txt");
  const std::vector<double> y = OcxoFractional();
  const AllanCurve curve = Batch(y, rows, AllanEstimator::kOverlapping);
  ASSERT_EQ(curve.points.size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    const AllanPoint& p = curve.points[i];
    const S32Row& r = rows[i];
    EXPECT_EQ(p.num_terms, r.n) << r.m;
    EXPECT_LT(Rel(p.adev, r.sigma), 2e-3) << r.m;
    if (p.noise_id == NoiseIdMethod::kLag1Acf) {
      EXPECT_EQ(p.alpha, r.alpha) << r.m;
    }
    const double edf = AllanEdf(r.alpha, r.m, 1, static_cast<int64_t>(y.size()) + 1);
    const DeviationBounds b =
        ChiSquareDeviationBounds(1.0, edf, kOneSigmaConfidence, ChiSquareMethod::kStable32);
    ExpectWithin1e4(b.lo, r.lo / r.sigma, false, "lo m=" + std::to_string(r.m));
    ExpectWithin1e4(b.hi, r.hi / r.sigma, r.m == 4096, "hi m=" + std::to_string(r.m));
  }
}

TEST(AllanStable32, OcxoNonOverlappingOctave) {
  if (!HaveData()) GTEST_SKIP() << "no " << kDir << " (shared reference data absent)";
  const std::vector<S32Row> rows = ReadStable32("adev_octave.txt");
  // At 1024 and 2048 (19 and 9 averages) the B1 ratio gives -1 where Stable32 gives -2 (bounds
  // then checked with its alpha); at 2048 (8 terms) the sigma differs by 1.1e-4.
  const Exceptions ex = {{1024, 2048}, {2048}, {}};
  ExpectMatches(Batch(OcxoFractional(), rows, AllanEstimator::kNonOverlapping), rows, 19983, ex,
                "adev octave");
}

// PHASE.DAT: Stable32 was run with alpha fixed at 0 (white FM) for the bounds, so alpha is not
// compared; the bounds are, with the EDF for alpha = 0. At AF 128 (6 terms, edf 4.2) the upper
// bound differs by 1.2e-4: Stable32's iterative chi-square inverse agrees with the exact one to
// about 4 digits (A. Wallin's comparison, see allan_confidence.h).
TEST(AllanStable32, PhaseDatNonOverlapping) {
  if (!HaveData()) GTEST_SKIP() << "no " << kDir << " (shared reference data absent)";
  const std::vector<double> y = PhaseDatFrequency();
  ASSERT_EQ(y.size(), 1000u);
  for (const char* name : {"phase_dat_adev.txt", "phase_dat_adev_octave.txt"}) {
    const std::vector<S32Row> rows = ReadStable32(name);
    ExpectMatches(Batch(y, rows, AllanEstimator::kNonOverlapping), rows, 1001, {{}, {}, {128}},
                  name, 0);
  }
}

// With the exact chi-square quantile the bounds differ from Stable32's only where its
// approximation is used (edf > 100); at or below 100 they agree to the table.
TEST(AllanStable32, ExactChiSquareAgreesUpTo100Edf) {
  if (!HaveData()) GTEST_SKIP() << "no " << kDir << " (shared reference data absent)";
  const std::vector<S32Row> rows = ReadStable32("adev_octave.txt");
  const AllanCurve curve =
      AllanAtFactors(OcxoFractional(), 1.0, Factors(rows), AllanEstimator::kNonOverlapping);
  int compared = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const AllanPoint& p = curve.points[i];
    if (p.edf > 100) {
      EXPECT_GT(Rel(p.adev_lo, rows[i].lo), 1e-5) << p.m;  // the approximation shows
      continue;
    }
    if (p.alpha != rows[i].alpha) continue;  // see OcxoNonOverlappingOctave
    ++compared;
    EXPECT_LT(Rel(p.adev_lo, rows[i].lo), 1e-4) << p.m;
    EXPECT_LT(Rel(p.adev_hi, rows[i].hi), 1e-4) << p.m;
  }
  EXPECT_GE(compared, 2);
}

}  // namespace
}  // namespace accelcal

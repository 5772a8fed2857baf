// Issue 17, item 11: the normality test of values near a double's limit gives a finite p, not
// "normal (JB p -nan)"; a value that is not finite is refused.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/analysis/normality.h"
#include "accelcal/base/error.h"

namespace accelcal::analysis {
namespace {

TEST(NormalityHardening, HugeValuesGiveTheSameVerdictAsSmallOnes) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> small, huge;
  for (int i = 0; i < 2000; ++i) {
    const double v = 3.0 + noise(rng);
    small.push_back(v);
    huge.push_back(v * 1e307);  // the squares, cubes and fourth powers overflow
  }
  const NormalityTest a = JarqueBera(small, 1.0);
  const NormalityTest b = JarqueBera(huge, 1e307);
  ASSERT_TRUE(std::isfinite(b.p_value)) << b.note;
  EXPECT_NEAR(b.p_value, a.p_value, 1e-9);
  EXPECT_EQ(b.verdict, a.verdict);
  EXPECT_EQ(b.note.find("nan"), std::string::npos) << b.note;
}

TEST(NormalityHardening, NonFiniteValuesAreRefused) {
  std::vector<double> x(100, 1.0);
  x[3] = 2.0;
  x[50] = INFINITY;
  EXPECT_THROW(JarqueBera(x, 1.0), Error);
}

}  // namespace
}  // namespace accelcal::analysis

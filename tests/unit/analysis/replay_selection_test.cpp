// ReplaySelection against std::nth_element: few distinct values (one pass), many (the radix
// passes), values apart only in their last bits (all four digits), every rank at the ends.
#include "accelcal/analysis/replay_selection.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"

namespace accelcal::analysis {
namespace {

double ByNthElement(std::vector<double> values, std::size_t k) {
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return values[k];
}

// Runs the passes until the selection knows; the number of passes into *passes.
double Select(const std::vector<double>& values, std::uint64_t k, int* passes) {
  ReplaySelection selection;
  for (int pass = 1; pass <= 8; ++pass) {
    for (double v : values) selection.Add(v);
    if (selection.EndPass(k)) {
      *passes = pass;
      return selection.Result();
    }
  }
  ADD_FAILURE() << "no answer after 8 passes";
  return NAN;
}

void ExpectAllRanks(const std::vector<double>& values, int max_passes) {
  for (std::size_t k : {std::size_t{0}, values.size() / 3, values.size() / 2,
                        values.size() - 1}) {
    int passes = 0;
    EXPECT_EQ(Select(values, k, &passes), ByNthElement(values, k)) << "k " << k;
    EXPECT_LE(passes, max_passes) << "k " << k;
  }
}

TEST(ReplaySelectionTest, AFewDistinctValuesTakeOnePass) {
  // A logger's intervals: 0.01 s and its neighbours from the subtraction of times.
  std::mt19937_64 rng(5);
  std::vector<double> values;
  const double choices[] = {0.01, 0.010000000000000009, 0.009999999999999787, 0.02};
  for (int i = 0; i < 10000; ++i) values.push_back(choices[rng() % 4]);
  ExpectAllRanks(values, 1);
  ExpectAllRanks(std::vector<double>(100, 0.001), 1);
}

TEST(ReplaySelectionTest, ManyDistinctValuesGoByDigits) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> jitter(0.0, 1e-4);
  std::vector<double> values;
  for (int i = 0; i < 20000; ++i) values.push_back(0.01 + jitter(rng));
  ExpectAllRanks(values, 4);
  // Spread over many binades.
  std::vector<double> wide;
  for (int i = 0; i < 5000; ++i) wide.push_back(std::exp(std::uniform_real_distribution<>(-30, 30)(rng)));
  ExpectAllRanks(wide, 4);
}

TEST(ReplaySelectionTest, ValuesApartInTheirLastBitsNeedAllFourDigits) {
  std::vector<double> values;
  double v = 1.0;
  for (int i = 0; i < 200; ++i) {
    values.push_back(v);
    v = std::nextafter(v, 2.0);
  }
  std::shuffle(values.begin(), values.end(), std::mt19937_64(7));
  int passes = 0;
  EXPECT_EQ(Select(values, 137, &passes), ByNthElement(values, 137));
  EXPECT_EQ(passes, 4);
}

TEST(ReplaySelectionTest, ARankPastTheValuesIsRefused) {
  ReplaySelection selection;
  selection.Add(1.0);
  selection.Add(2.0);
  EXPECT_THROW(selection.EndPass(2), Error);
}

TEST(ReplaySelectionTest, ValuesChangedBetweenPassesAreRefused) {
  std::mt19937_64 rng(8);
  std::vector<double> values;
  for (int i = 0; i < 1000; ++i) values.push_back(1.0 + static_cast<double>(rng() % 100000) * 1e-9);
  ReplaySelection selection;
  for (double v : values) selection.Add(v);
  ASSERT_FALSE(selection.EndPass(999));  // the largest: the last bucket of the first digit
  for (double& v : values) v = 0.5;      // none of them in that bucket now
  for (double v : values) selection.Add(v);
  EXPECT_THROW(selection.EndPass(999), Error);
}

}  // namespace
}  // namespace accelcal::analysis

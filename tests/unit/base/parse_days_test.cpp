// ParseDays (base/duration_text.h): the windows and intervals of `accelcal lab due --within` and
// `lab device-type --interval`.
#include <gtest/gtest.h>

#include "accelcal/base/duration_text.h"

namespace accelcal {
namespace {

TEST(ParseDays, DaysWeeksAndYears) {
  EXPECT_EQ(ParseDays("30d"), 30);
  EXPECT_EQ(ParseDays("30"), 30);
  EXPECT_EQ(ParseDays("30 days"), 30);
  EXPECT_EQ(ParseDays("0d"), 0);
  EXPECT_EQ(ParseDays("6w"), 42);
  EXPECT_EQ(ParseDays("1y"), 365);
  EXPECT_EQ(ParseDays("2 years"), 730);
}

TEST(ParseDays, AnythingElseIsNotADayCount) {
  for (const char* text : {"", "d", "-3d", "1.5d", "3m", "30 h", "30dd", " 30d", "99999999999d"})
    EXPECT_EQ(ParseDays(text), std::nullopt) << text;
}

}  // namespace
}  // namespace accelcal

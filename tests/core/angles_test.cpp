#include "core/angles.h"

#include <gtest/gtest.h>

namespace canopy {
namespace {

TEST(WrapAngle, MapsIntoHalfOpenIntervalAroundZero) {
  EXPECT_DOUBLE_EQ(wrapAngle(0.0), 0.0);
  EXPECT_DOUBLE_EQ(wrapAngle(kPi), kPi);
  EXPECT_DOUBLE_EQ(wrapAngle(-kPi), kPi);  // (−π, π]
  EXPECT_NEAR(wrapAngle(3 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_NEAR(wrapAngle(-5 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_NEAR(wrapAngle(20 * kPi + 0.1), 0.1, 1e-12);
}

TEST(WrapAnglePositive, MapsIntoZeroToTwoPi) {
  EXPECT_DOUBLE_EQ(wrapAnglePositive(0.0), 0.0);
  EXPECT_NEAR(wrapAnglePositive(-kPi / 2), 3 * kPi / 2, 1e-15);
  EXPECT_NEAR(wrapAnglePositive(kTwoPi + 0.25), 0.25, 1e-15);
  EXPECT_LT(wrapAnglePositive(-1e-18), kTwoPi);
}

}  // namespace
}  // namespace canopy

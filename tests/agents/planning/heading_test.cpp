#include "agents/planning/heading.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/random.h"

namespace canopy::agents::planning {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Against glibc's cos and sin (a second, independent implementation): within 2.3e-16 = about
// 2 ulp of 1 over the swarm's box [0, 2π], and of unit length to 4.5e-16.
TEST(UnitHeading, MatchesLibmCosAndSinOverTheHeadingBox) {
  RandomStream rng(8, "heading-test");
  double worst = 0.0;
  for (int k = 0; k <= 200000; ++k) {
    const double theta = k < 100000 ? kTwoPi * k / 100000 : rng.uniform(0.0, kTwoPi);
    const Vec2 u = unitHeading(theta);
    worst = std::max({worst, std::abs(u.x() - std::cos(theta)), std::abs(u.y() - std::sin(theta))});
    ASSERT_NEAR(u.squaredNorm(), 1.0, 4.5e-16) << theta;
  }
  EXPECT_LE(worst, 2.3e-16);
}

// At the quarter turns one component is the tiny r = θ − n π/2 (θ a double near n π/2): the
// reduction leaves an absolute error of 3.5e-27 per quarter (π/2 − P1 − P1t), far below an ulp of
// the action's other component, though not a relative ulp of r itself.
TEST(UnitHeading, QuarterTurnsAndTheBoxEnds) {
  EXPECT_EQ(unitHeading(0.0), Vec2(1.0, 0.0));
  EXPECT_EQ(unitHeading(kTwoPi).x(), 1.0);
  EXPECT_NEAR(unitHeading(kTwoPi).y(), std::sin(kTwoPi), 2e-26);  // −2.4e-16
  EXPECT_NEAR(unitHeading(std::numbers::pi / 2).x(), std::cos(std::numbers::pi / 2), 1e-26);
  EXPECT_EQ(unitHeading(std::numbers::pi / 2).y(), 1.0);
  EXPECT_EQ(unitHeading(std::numbers::pi).x(), -1.0);
  EXPECT_NEAR(unitHeading(std::numbers::pi).y(), std::sin(std::numbers::pi), 1e-26);
  EXPECT_NEAR(unitHeading(1.5 * std::numbers::pi).x(), std::cos(1.5 * std::numbers::pi), 2e-26);
  EXPECT_EQ(unitHeading(1.5 * std::numbers::pi).y(), -1.0);
}

// Small headings keep their relative accuracy (sin θ ≈ θ), as the exact reduction promises.
TEST(UnitHeading, SmallHeadingsAreRelativelyAccurate) {
  for (double theta = 1e-300; theta < 0.5; theta *= 3.7) {
    EXPECT_NEAR(unitHeading(theta).y(), std::sin(theta), 2.3e-16 * std::sin(theta)) << theta;
  }
}

}  // namespace
}  // namespace canopy::agents::planning

// GOSPA (α = 2) against values computed by hand from its definition.
#include "metrics/gospa.h"

#include <gtest/gtest.h>

#include <cmath>

#include "metrics/ospa.h"

namespace canopy::metrics {
namespace {

TEST(Gospa, EmptySetsCostHalfTheCutOffPerPoint) {
  Gospa gospa(50.0, 2.0);
  const std::vector<Vec2> none, three{Vec2(0, 0), Vec2(5, 5), Vec2(9, 1)};
  EXPECT_EQ(gospa(none, none), 0.0);
  // Three missed targets: (3 · 50²/2)^{1/2} = √3750 = 61.2372…
  EXPECT_NEAR(gospa(three, none), 61.237243569579, 1e-9);
  EXPECT_NEAR(gospa(none, three), 61.237243569579, 1e-9);
}

// Truth {(0, 0), (10, 0)}, one estimate (3, 4): it is 5 m from the first target and √65 m from
// the second, so the best assignment pairs it with the first (5² = 25 < 65) and the second
// target is missed: GOSPA = (25 + 50²/2)^{1/2} = √1275 = 35.7071…, while OSPA normalises by
// n = 2: ((25 + 50²)/2)^{1/2} = √1262.5 = 35.5317….
TEST(Gospa, MatchesAHandComputedValueBesideOspa) {
  Gospa gospa(50.0, 2.0);
  Ospa ospa(50.0, 2.0);
  const std::vector<Vec2> truth{Vec2(0, 0), Vec2(10, 0)}, estimates{Vec2(3, 4)};
  EXPECT_NEAR(gospa(truth, estimates), std::sqrt(1275.0), 1e-12);
  EXPECT_NEAR(gospa(truth, estimates), 35.707142142714, 1e-9);
  EXPECT_NEAR(ospa(truth, estimates), std::sqrt(1262.5), 1e-12);
}

// Beyond the cut-off a pair costs c^p, the same as one miss and one false target (2 · c^p/2):
// one target at the origin, one estimate 100 m away, c = 50: GOSPA = 50.
TEST(Gospa, FarPairsCostTheSameAsAMissAndAFalseTarget) {
  Gospa gospa(50.0, 2.0);
  const std::vector<Vec2> truth{Vec2(0, 0)}, estimates{Vec2(100, 0)};
  EXPECT_NEAR(gospa(truth, estimates), 50.0, 1e-12);
  // Two perfect estimates and one false one 3 m off: (0 + 0 + 1250)^{1/2}.
  const std::vector<Vec2> two{Vec2(1, 1), Vec2(20, 5)}, three{Vec2(20, 5), Vec2(1, 1), Vec2(23, 5)};
  EXPECT_NEAR(gospa(two, three), std::sqrt(1250.0), 1e-12);
}

}  // namespace
}  // namespace canopy::metrics
